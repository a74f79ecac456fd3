# Amplification |R(z)| of one step on y' = λy, z = hλ real (damped modes), for the four course
# integrators. A step is stable where |R(z)| ≤ 1.   gnuplot stability.gp  → stability.svg
set terminal svg size 760,480 font "DejaVu Sans,13" background rgb "white"
set output "stability.svg"
set title "One step on y' = λy with z = hλ real: stable where |R(z)| ≤ 1"
set xlabel "z = h λ   (negative: a damped mode; the course cube's top mode at h = 0.001 is z ≈ −0.97)"
set ylabel "|R(z)|"
set xrange [-3.2:0.3]
set yrange [0:2.5]
set grid
set key outside below box
set samples 800
set arrow from -3.2,1 to 0.3,1 nohead dt 2 lw 2 lc rgb "#222222"
set arrow from -0.97,0 to -0.97,2.5 nohead dt 3 lw 1.5 lc rgb "#7d3c98"
set label "−1 (course implicit Euler's limit)" at -1.0,2.3 right tc rgb "#c0392b"
set label "−2" at -2.0,0.12 center
set label "−2.785" at -2.785,0.12 center
explicit(z) = abs(1 + z)
implicit(z) = abs(1 + z + z**2)
midpoint(z) = abs(1 + z + z**2/2)
rk4(z) = abs(1 + z + z**2/2 + z**3/6 + z**4/24)
plot explicit(x) lw 2.5 lc rgb "#2471a3" title "explicit Euler  1 + z", \
     implicit(x) lw 2.5 lc rgb "#c0392b" title "course implicit Euler  1 + z + z²", \
     midpoint(x) lw 2.5 dt 4 lc rgb "#1e8449" title "midpoint  1 + z + z²/2", \
     rk4(x) lw 2.5 lc rgb "#d35400" title "RK4  1 + z + z²/2 + z³/6 + z⁴/24"
