#!/usr/bin/env python3
"""Writes the handout's geometry figures (SVG) from the physics contract's definitions.

    python3 assignments/a1/handout/figures/make_figures.py      # rewrites springs.svg, plane.svg, bowl.svg

stability.svg is drawn by gnuplot from stability.gp. The numbers in bowl.svg are the course's 2023
terrain (R = 9, c_y = 9/sqrt(2), rim at y = 0), computed here, not typed in.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
FONT = 'font-family="DejaVu Sans, Arial, sans-serif"'


def svg(width, height, body):
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
            f'viewBox="0 0 {width} {height}" {FONT} font-size="14">\n'
            '<defs>\n' + ''.join(
                f'<marker id="arrow-{name}" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" '
                f'markerHeight="7" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="{col}"/></marker>\n'
                for name, col in COLORS.items()) +
            '</defs>\n<rect width="100%" height="100%" fill="white"/>\n' + body + '</svg>\n')


COLORS = {"black": "#222222", "red": "#c0392b", "blue": "#2471a3", "green": "#1e8449",
          "orange": "#d35400", "purple": "#7d3c98", "grey": "#888888"}


def line(x1, y1, x2, y2, color="black", width=2, dash=None, arrow=False):
    """A segment; with arrow=True an explicit triangular head at (x2, y2) (no SVG markers, so that
    every renderer draws it)."""
    d = f' stroke-dasharray="{dash}"' if dash else ''
    out = ''
    if arrow:
        length = math.hypot(x2 - x1, y2 - y1)
        ux, uy = (x2 - x1) / length, (y2 - y1) / length
        head = 6 + 2.2 * width
        bx, by = x2 - head * ux, y2 - head * uy
        px, py = -uy * head * 0.45, ux * head * 0.45
        out = (f'<polygon points="{x2:.1f},{y2:.1f} {bx + px:.1f},{by + py:.1f} {bx - px:.1f},{by - py:.1f}" '
               f'fill="{COLORS[color]}"/>\n')
        x2, y2 = bx + 0.5 * head * ux, by + 0.5 * head * uy
    return (f'<line x1="{x1:.1f}" y1="{y1:.1f}" x2="{x2:.1f}" y2="{y2:.1f}" '
            f'stroke="{COLORS[color]}" stroke-width="{width}"{d}/>\n') + out


def text(x, y, s, color="black", size=14, anchor="start", style=""):
    return (f'<text x="{x:.1f}" y="{y:.1f}" fill="{COLORS[color]}" font-size="{size}" '
            f'text-anchor="{anchor}" {style}>{s}</text>\n')


def dot(x, y, r=4, color="grey", fill=None):
    return (f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{r}" fill="{COLORS[fill or color]}" '
            f'stroke="{COLORS[color]}"/>\n')


# ---------------------------------------------------------------------------------------------
# Springs: four panels, each a 3x3x3 lattice in oblique projection, one owner particle and the
# springs it owns (forward directions only, contract section 2).
# ---------------------------------------------------------------------------------------------
def project(ox, oy, i, j, k, s=62):
    return ox + s * i + 0.45 * s * k, oy - s * j - 0.30 * s * k


def springs_figure():
    panels = [
        ("A1.T1 structural: (1,0,0) (0,1,0) (0,0,1), rest s", (0, 1, 1),
         [(1, 0, 0), (0, 1, 0), (0, 0, 1)], "blue"),
        ("A1.T2 shear, face diagonals (6), rest s&#8730;2", (0, 1, 1),
         [(0, 1, 1), (0, 1, -1), (1, 0, 1), (1, 0, -1), (1, 1, 0), (1, -1, 0)], "green"),
        ("A1.T2 shear, body diagonals (4), rest s&#8730;3", (0, 1, 1),
         [(1, 1, 1), (1, 1, -1), (1, -1, 1), (1, -1, -1)], "orange"),
        ("A1.T3 bending: (2,0,0) (0,2,0) (0,0,2), rest 2s", (0, 0, 0),
         [(2, 0, 0), (0, 2, 0), (0, 0, 2)], "purple"),
    ]
    W, H = 400, 330
    body = ""
    for p, (title, owner, offsets, color) in enumerate(panels):
        px, py = (p % 2) * W, (p // 2) * H
        ox, oy = px + 90, py + 255
        body += f'<rect x="{px + 4}" y="{py + 4}" width="{W - 8}" height="{H - 8}" fill="none" stroke="#dddddd"/>\n'
        body += text(px + 14, py + 26, title, size=15, style='font-weight="bold"')
        # lattice edges (light) and particles
        for i in range(3):
            for j in range(3):
                for k in range(3):
                    x1, y1 = project(ox, oy, i, j, k)
                    for di, dj, dk in ((1, 0, 0), (0, 1, 0), (0, 0, 1)):
                        if i + di < 3 and j + dj < 3 and k + dk < 3:
                            x2, y2 = project(ox, oy, i + di, j + dj, k + dk)
                            body += line(x1, y1, x2, y2, "grey", 0.6, dash="3,3")
        for i in range(3):
            for j in range(3):
                for k in range(3):
                    x, y = project(ox, oy, i, j, k)
                    body += dot(x, y, 3, "grey")
        oxp, oyp = project(ox, oy, *owner)
        for o in offsets:
            t = tuple(a + b for a, b in zip(owner, o))
            x2, y2 = project(ox, oy, *t)
            body += line(oxp, oyp, x2, y2, color, 2.6)
            body += dot(x2, y2, 5, color)
            label = "(" + ",".join(("&#8722;1" if c == -1 else str(c)) for c in o) + ")"
            body += text(x2 + 7, y2 - 6, label, color, 12)
        body += dot(oxp, oyp, 7, "red")
        body += text(oxp - 12, oyp + 4, "a", "red", 15, "end")
        # axes
        ax, ay = px + 320, py + 300
        body += line(ax, ay, ax + 36, ay, "black", 1.5, arrow=True) + text(ax + 40, ay + 4, "i (x)", size=12)
        body += line(ax, ay, ax, ay - 36, "black", 1.5, arrow=True) + text(ax - 4, ay - 40, "j (y)", size=12, anchor="end")
        body += line(ax, ay, ax + 22, ay - 15, "black", 1.5, arrow=True) + text(ax + 24, ay - 20, "k (z)", size=12)
    body += text(10, 2 * H + 20, "Each particle a = (i, j, k) owns only the springs towards its forward neighbours "
                 "b = a + offset, when b exists;", size=13)
    body += text(10, 2 * H + 38, "the rest length is |x_b &#8722; x_a| when the spring is built. "
                 "No spring is built twice.", size=13)
    return svg(2 * W, 2 * H + 50, body)


# ---------------------------------------------------------------------------------------------
# Plane: the collision test and the v_N / v_T split (contract sections 3-5), cross-section.
# ---------------------------------------------------------------------------------------------
def plane_figure():
    b = ""
    y0 = 230  # the plane y = 0 on screen
    hole_l, hole_r = 600, 760
    b += f'<rect x="30" y="{y0}" width="{hole_l - 30}" height="170" fill="#eeeeee"/>\n'
    b += f'<rect x="{hole_r}" y="{y0}" width="{880 - hole_r}" height="170" fill="#eeeeee"/>\n'
    b += line(30, y0, hole_l, y0, "black", 3) + line(hole_r, y0, 880, y0, "black", 3)
    b += line(30, y0 - 20, 880, y0 - 20, "grey", 1.2, dash="6,4")
    b += text(884, y0 - 16, "&#966; = &#949;", "grey", 13)
    b += text(884, y0 + 5, "&#966; = 0", size=13)
    b += text(40, y0 + 160, "plane: point p, unit normal N, &#966;(x) = N&#183;(x &#8722; p)   (below the plane &#966; &lt; 0)",
              size=14)
    b += line(80, y0, 80, y0 - 80, "black", 2.5, arrow=True) + text(88, y0 - 70, "N (unit length!)", size=14)
    # particle and velocities
    px, py = 300, y0 - 10
    vx, vy = 110, 100  # v: right and down (screen y grows downwards)
    kr = 0.8
    b += line(px, py, px, py + vy, "blue", 2.5, arrow=True)
    b += text(px - 8, py + vy + 2, "v_N = (N&#183;v) N", "blue", 14, "end")
    b += line(px, py, px + vx, py, "green", 2.5, arrow=True)
    b += text(px + vx + 8, py + 34, "v_T = v &#8722; v_N", "green", 14)
    b += line(px + vx, py, px + vx, py + vy, "grey", 1, dash="3,3")
    b += line(px, py + vy, px + vx, py + vy, "grey", 1, dash="3,3")
    b += line(px, py, px + vx, py + vy, "red", 3, arrow=True) + text(px + vx + 6, py + vy + 6, "v", "red", 16)
    b += line(px, py, px + vx, py - kr * vy, "orange", 3, arrow=True)
    b += text(px + vx + 8, py - kr * vy, "v&#8242; = &#8722;k_r v_N + v_T", "orange", 14)
    b += text(px + vx + 8, py - kr * vy + 17, "(drawn with k_r = 0.8)", "orange", 12)
    b += dot(px, py, 7, "black", "red")
    b += text(px - 12, py - 10, "x", size=16, anchor="end")
    b += text(30, 34, "collides when  &#966;(x) &lt; &#949;  and  N&#183;v &lt; 0  and  x is not over the hole",
              size=15, style='font-weight="bold"')
    b += text(30, 56, "then  v &#8592; &#8722;k_r v_N + v_T   (positions do not change)", size=15)
    # hole
    hx = (hole_l + hole_r) / 2
    b += line(hx, y0 + 8, hx, y0 - 4, "purple", 1.5) + text(hx - 6, y0 + 26, "h", "purple", 14, "end")
    b += line(hx, y0 + 40, hole_r, y0 + 40, "purple", 1.5, arrow=True)
    b += text((hx + hole_r) / 2, y0 + 58, "r_h", "purple", 14, "middle")
    qx, qy = hx - 40, y0 - 10
    b += line(qx, qy, qx, qy + 60, "red", 2.5, arrow=True) + dot(qx, qy, 7, "black", "red")
    b += text(hx, y0 - 175, "over the hole (distance to h,", "purple", 13, "middle")
    b += text(hx, y0 - 159, "measured in the plane, &lt; r_h):", "purple", 13, "middle")
    b += text(hx, y0 - 143, "no collision, no contact", "purple", 13, "middle")
    return svg(940, 410, b)


# ---------------------------------------------------------------------------------------------
# Bowl: cross-section through the bowl's vertical axis, course 2023 numbers.
# ---------------------------------------------------------------------------------------------
def bowl_figure():
    R = 9.0
    cy = 9.0 / math.sqrt(2.0)
    y_rim = 0.0
    r_rim = math.sqrt(R * R - (cy - y_rim) ** 2)
    S = 21.0  # pixels per metre
    ox, oy = 360, 400  # screen position of (axis, y = 0)

    def P(x, y):
        return ox + S * x, oy - S * y

    b = ""
    cx_s, cy_s = P(0, cy)
    # full sphere, dashed; the cap below the rim, shaded
    b += f'<circle cx="{cx_s:.1f}" cy="{cy_s:.1f}" r="{S * R:.1f}" fill="none" stroke="#999999" stroke-dasharray="6,5"/>\n'
    a0 = math.atan2(y_rim - cy, -r_rim)
    a1 = math.atan2(y_rim - cy, r_rim)
    pts = []
    n = 60
    for t in range(n + 1):
        a = a0 + (a1 - a0 + (2 * math.pi if a1 < a0 else 0)) * t / n
        pts.append(P(R * math.cos(a), cy + R * math.sin(a)))
    # a0 is at the lower left; go the short way through the bottom
    pts = []
    start = math.pi + math.atan2(cy - y_rim, r_rim)  # angle of the left rim point
    end = 2 * math.pi - math.atan2(cy - y_rim, r_rim)
    for t in range(n + 1):
        a = start + (end - start) * t / n
        pts.append(P(R * math.cos(a), cy + R * math.sin(a)))
    path = "M " + " L ".join(f"{x:.1f},{y:.1f}" for x, y in pts)
    b += f'<path d="{path} Z" fill="#dbe9f6" stroke="{COLORS["blue"]}" stroke-width="3"/>\n'
    # the floor plane with its hole (the rim)
    lx, _ = P(-r_rim, 0)
    rx, _ = P(r_rim, 0)
    b += line(20, oy, lx, oy, "black", 3) + line(rx, oy, 760, oy, "black", 3)
    b += text(560, oy + 22, "floor y = 0, hole radius = rim radius", size=12)
    b += line(20, oy - 9, 760, oy - 9, "grey", 1, dash="5,4")
    b += text(24, oy - 14, "y_rim + &#949; (&#949; exaggerated)", "grey", 12)
    # centre, radius, rim radius
    b += dot(cx_s, cy_s, 5, "black") + text(cx_s + 8, cy_s - 6, f"c = (c_x, {cy:.3f}, c_z)", size=13)
    b += line(cx_s, cy_s, rx, oy, "black", 1.5, arrow=True)
    b += text((cx_s + rx) / 2 + 10, (cy_s + oy) / 2, f"R = {R:g}", size=13)
    b += line(cx_s, oy + 22, rx, oy + 22, "purple", 1.8, arrow=True)
    b += line(cx_s, oy + 14, cx_s, oy + 30, "purple", 1.5)
    b += text((cx_s + rx) / 2, oy + 40, f"rim radius &#8730;(R&#178; &#8722; (c_y &#8722; y_rim)&#178;) = {r_rim:.3f}",
              "purple", 12, "middle")
    b += line(cx_s, cy_s, cx_s, P(0, cy - R)[1] + 20, "grey", 1, dash="2,4")
    b += text(cx_s + 4, P(0, cy - R)[1] + 34, "vertical axis", "grey", 12)
    # a particle on the wall, with its inward normal
    ang = math.radians(235)
    wx, wy = R * math.cos(ang), cy + R * math.sin(ang)
    xs, ys = P(wx * 0.995, cy + (wy - cy) * 0.995)
    nx, ny = -math.cos(ang), -math.sin(ang)
    b += line(xs, ys, xs + 70 * nx, ys - 70 * ny, "black", 2.5, arrow=True)
    b += text(xs + 70 * nx + 6, ys - 70 * ny + 2, "N = (c &#8722; x)/|c &#8722; x|", size=13)
    b += line(xs, ys, xs + 40, ys + 40, "red", 2.5, arrow=True) + text(xs + 44, ys + 52, "v (N&#183;v &lt; 0)", "red", 13)
    b += dot(xs, ys, 6, "black", "red")
    b += text(xs - 14, ys + 26, "x: &#966; = R &#8722; |x &#8722; c| &lt; &#949;", "red", 13, "end")
    # particle above the rim, inside the sphere: not in the bowl's extent
    ux, uy = P(-7.2, 2.2)
    b += dot(ux, uy, 6, "black", "grey")
    b += text(ux - 10, uy - 8, "above y_rim + &#949;: not the bowl", "grey", 12, "end")
    # particle resting on the floor outside the rim: plane only
    fx, fy = P(r_rim + 2.6, 0.12)
    b += dot(fx, fy, 6, "black", "green")
    b += text(fx - 30, fy - 56, "on the floor, horizontal distance", "green", 12)
    b += text(fx - 30, fy - 40, "to the axis &gt; rim radius:", "green", 12)
    b += text(fx - 30, fy - 24, "plane only, never the bowl", "green", 12)
    b += text(20, 24, "bowl extent:  x_y &#8804; y_rim + &#949;   and   horizontal distance to the axis &#8804; rim radius",
              size=14, style='font-weight="bold"')
    return svg(780, 500, b)


if __name__ == "__main__":
    for name, make in (("springs.svg", springs_figure), ("plane.svg", plane_figure),
                       ("bowl.svg", bowl_figure)):
        with open(os.path.join(HERE, name), "w", encoding="utf-8") as f:
            f.write(make())
        print("wrote", os.path.join(HERE, name))
