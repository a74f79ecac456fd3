# Work-precision plot written by `jelly study accuracy`; run: gnuplot accuracy-free-fall.gp (in this folder)
set datafile missing 'nan'
set logscale xy
set grid
set key top right font ',9'
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'RMS position error [m]'
set pointsize 1.0
set terminal svg size 1500,520 dynamic enhanced font 'sans,11' background '#ffffff'
set output 'accuracy-free-fall.svg'
set multiplot layout 1,3 title "Free fall (n = 4 cube, smooth), T = 1.2 s" noenhanced font ',12'
set ylabel 'wall time per simulated second [s]'
set arrow 1 from 1, graph 0 to 1, graph 1 nohead dashtype 2 lc rgb '#999999'
plot 'accuracy-free-fall.dat' index 0 using 2:3 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#d62728' title 'explicit_euler' noenhanced, \
     'accuracy-free-fall.dat' index 1 using 2:3 with points pt 2 ps 1.6 lw 2 lc rgb '#d62728' title 'explicit_euler unstable' noenhanced, \
     'accuracy-free-fall.dat' index 2 using 2:3 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#ff7f0e' title 'implicit_euler' noenhanced, \
     'accuracy-free-fall.dat' index 3 using 2:3 with points pt 2 ps 1.6 lw 2 lc rgb '#ff7f0e' title 'implicit_euler unstable' noenhanced, \
     'accuracy-free-fall.dat' index 4 using 2:3 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#2ca02c' title 'midpoint' noenhanced, \
     'accuracy-free-fall.dat' index 5 using 2:3 with points pt 2 ps 1.6 lw 2 lc rgb '#2ca02c' title 'midpoint unstable' noenhanced, \
     'accuracy-free-fall.dat' index 6 using 2:3 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#1f77b4' title 'rk4' noenhanced, \
     'accuracy-free-fall.dat' index 7 using 2:3 with points pt 2 ps 1.6 lw 2 lc rgb '#1f77b4' title 'rk4 unstable' noenhanced, \
     'accuracy-free-fall.dat' index 8 using 2:3 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#9467bd' title 'symplectic_euler' noenhanced, \
     'accuracy-free-fall.dat' index 9 using 2:3 with points pt 2 ps 1.6 lw 2 lc rgb '#9467bd' title 'symplectic_euler unstable' noenhanced, \
     'accuracy-free-fall.dat' index 10 using 2:3 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#555555' title 'backward_euler' noenhanced
unset arrow 1
set ylabel 'force evaluations (+ CG mat-vec products)'
set arrow 1 from 1, graph 0 to 1, graph 1 nohead dashtype 2 lc rgb '#999999'
plot 'accuracy-free-fall.dat' index 0 using 2:4 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#d62728' title 'explicit_euler' noenhanced, \
     'accuracy-free-fall.dat' index 1 using 2:4 with points pt 2 ps 1.6 lw 2 lc rgb '#d62728' title 'explicit_euler unstable' noenhanced, \
     'accuracy-free-fall.dat' index 2 using 2:4 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#ff7f0e' title 'implicit_euler' noenhanced, \
     'accuracy-free-fall.dat' index 3 using 2:4 with points pt 2 ps 1.6 lw 2 lc rgb '#ff7f0e' title 'implicit_euler unstable' noenhanced, \
     'accuracy-free-fall.dat' index 4 using 2:4 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#2ca02c' title 'midpoint' noenhanced, \
     'accuracy-free-fall.dat' index 5 using 2:4 with points pt 2 ps 1.6 lw 2 lc rgb '#2ca02c' title 'midpoint unstable' noenhanced, \
     'accuracy-free-fall.dat' index 6 using 2:4 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#1f77b4' title 'rk4' noenhanced, \
     'accuracy-free-fall.dat' index 7 using 2:4 with points pt 2 ps 1.6 lw 2 lc rgb '#1f77b4' title 'rk4 unstable' noenhanced, \
     'accuracy-free-fall.dat' index 8 using 2:4 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#9467bd' title 'symplectic_euler' noenhanced, \
     'accuracy-free-fall.dat' index 9 using 2:4 with points pt 2 ps 1.6 lw 2 lc rgb '#9467bd' title 'symplectic_euler unstable' noenhanced, \
     'accuracy-free-fall.dat' index 10 using 2:4 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#555555' title 'backward_euler' noenhanced
unset arrow 1
set ylabel 'step h [s]'
set arrow 1 from 1, graph 0 to 1, graph 1 nohead dashtype 2 lc rgb '#999999'
plot 'accuracy-free-fall.dat' index 0 using 2:1 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#d62728' title 'explicit_euler' noenhanced, \
     'accuracy-free-fall.dat' index 1 using 2:1 with points pt 2 ps 1.6 lw 2 lc rgb '#d62728' title 'explicit_euler unstable' noenhanced, \
     'accuracy-free-fall.dat' index 2 using 2:1 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#ff7f0e' title 'implicit_euler' noenhanced, \
     'accuracy-free-fall.dat' index 3 using 2:1 with points pt 2 ps 1.6 lw 2 lc rgb '#ff7f0e' title 'implicit_euler unstable' noenhanced, \
     'accuracy-free-fall.dat' index 4 using 2:1 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#2ca02c' title 'midpoint' noenhanced, \
     'accuracy-free-fall.dat' index 5 using 2:1 with points pt 2 ps 1.6 lw 2 lc rgb '#2ca02c' title 'midpoint unstable' noenhanced, \
     'accuracy-free-fall.dat' index 6 using 2:1 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#1f77b4' title 'rk4' noenhanced, \
     'accuracy-free-fall.dat' index 7 using 2:1 with points pt 2 ps 1.6 lw 2 lc rgb '#1f77b4' title 'rk4 unstable' noenhanced, \
     'accuracy-free-fall.dat' index 8 using 2:1 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#9467bd' title 'symplectic_euler' noenhanced, \
     'accuracy-free-fall.dat' index 9 using 2:1 with points pt 2 ps 1.6 lw 2 lc rgb '#9467bd' title 'symplectic_euler unstable' noenhanced, \
     'accuracy-free-fall.dat' index 10 using 2:1 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#555555' title 'backward_euler' noenhanced
unset arrow 1
unset multiplot
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1500,520 enhanced font 'sans,10'
  set output 'accuracy-free-fall.png'
  set multiplot layout 1,3 title "Free fall (n = 4 cube, smooth), T = 1.2 s" noenhanced font ',12'
  set ylabel 'wall time per simulated second [s]'
  set arrow 1 from 1, graph 0 to 1, graph 1 nohead dashtype 2 lc rgb '#999999'
  plot 'accuracy-free-fall.dat' index 0 using 2:3 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#d62728' title 'explicit_euler' noenhanced, \
       'accuracy-free-fall.dat' index 1 using 2:3 with points pt 2 ps 1.6 lw 2 lc rgb '#d62728' title 'explicit_euler unstable' noenhanced, \
       'accuracy-free-fall.dat' index 2 using 2:3 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#ff7f0e' title 'implicit_euler' noenhanced, \
       'accuracy-free-fall.dat' index 3 using 2:3 with points pt 2 ps 1.6 lw 2 lc rgb '#ff7f0e' title 'implicit_euler unstable' noenhanced, \
       'accuracy-free-fall.dat' index 4 using 2:3 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#2ca02c' title 'midpoint' noenhanced, \
       'accuracy-free-fall.dat' index 5 using 2:3 with points pt 2 ps 1.6 lw 2 lc rgb '#2ca02c' title 'midpoint unstable' noenhanced, \
       'accuracy-free-fall.dat' index 6 using 2:3 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#1f77b4' title 'rk4' noenhanced, \
       'accuracy-free-fall.dat' index 7 using 2:3 with points pt 2 ps 1.6 lw 2 lc rgb '#1f77b4' title 'rk4 unstable' noenhanced, \
       'accuracy-free-fall.dat' index 8 using 2:3 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#9467bd' title 'symplectic_euler' noenhanced, \
       'accuracy-free-fall.dat' index 9 using 2:3 with points pt 2 ps 1.6 lw 2 lc rgb '#9467bd' title 'symplectic_euler unstable' noenhanced, \
       'accuracy-free-fall.dat' index 10 using 2:3 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#555555' title 'backward_euler' noenhanced
  unset arrow 1
  set ylabel 'force evaluations (+ CG mat-vec products)'
  set arrow 1 from 1, graph 0 to 1, graph 1 nohead dashtype 2 lc rgb '#999999'
  plot 'accuracy-free-fall.dat' index 0 using 2:4 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#d62728' title 'explicit_euler' noenhanced, \
       'accuracy-free-fall.dat' index 1 using 2:4 with points pt 2 ps 1.6 lw 2 lc rgb '#d62728' title 'explicit_euler unstable' noenhanced, \
       'accuracy-free-fall.dat' index 2 using 2:4 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#ff7f0e' title 'implicit_euler' noenhanced, \
       'accuracy-free-fall.dat' index 3 using 2:4 with points pt 2 ps 1.6 lw 2 lc rgb '#ff7f0e' title 'implicit_euler unstable' noenhanced, \
       'accuracy-free-fall.dat' index 4 using 2:4 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#2ca02c' title 'midpoint' noenhanced, \
       'accuracy-free-fall.dat' index 5 using 2:4 with points pt 2 ps 1.6 lw 2 lc rgb '#2ca02c' title 'midpoint unstable' noenhanced, \
       'accuracy-free-fall.dat' index 6 using 2:4 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#1f77b4' title 'rk4' noenhanced, \
       'accuracy-free-fall.dat' index 7 using 2:4 with points pt 2 ps 1.6 lw 2 lc rgb '#1f77b4' title 'rk4 unstable' noenhanced, \
       'accuracy-free-fall.dat' index 8 using 2:4 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#9467bd' title 'symplectic_euler' noenhanced, \
       'accuracy-free-fall.dat' index 9 using 2:4 with points pt 2 ps 1.6 lw 2 lc rgb '#9467bd' title 'symplectic_euler unstable' noenhanced, \
       'accuracy-free-fall.dat' index 10 using 2:4 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#555555' title 'backward_euler' noenhanced
  unset arrow 1
  set ylabel 'step h [s]'
  set arrow 1 from 1, graph 0 to 1, graph 1 nohead dashtype 2 lc rgb '#999999'
  plot 'accuracy-free-fall.dat' index 0 using 2:1 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#d62728' title 'explicit_euler' noenhanced, \
       'accuracy-free-fall.dat' index 1 using 2:1 with points pt 2 ps 1.6 lw 2 lc rgb '#d62728' title 'explicit_euler unstable' noenhanced, \
       'accuracy-free-fall.dat' index 2 using 2:1 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#ff7f0e' title 'implicit_euler' noenhanced, \
       'accuracy-free-fall.dat' index 3 using 2:1 with points pt 2 ps 1.6 lw 2 lc rgb '#ff7f0e' title 'implicit_euler unstable' noenhanced, \
       'accuracy-free-fall.dat' index 4 using 2:1 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#2ca02c' title 'midpoint' noenhanced, \
       'accuracy-free-fall.dat' index 5 using 2:1 with points pt 2 ps 1.6 lw 2 lc rgb '#2ca02c' title 'midpoint unstable' noenhanced, \
       'accuracy-free-fall.dat' index 6 using 2:1 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#1f77b4' title 'rk4' noenhanced, \
       'accuracy-free-fall.dat' index 7 using 2:1 with points pt 2 ps 1.6 lw 2 lc rgb '#1f77b4' title 'rk4 unstable' noenhanced, \
       'accuracy-free-fall.dat' index 8 using 2:1 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#9467bd' title 'symplectic_euler' noenhanced, \
       'accuracy-free-fall.dat' index 9 using 2:1 with points pt 2 ps 1.6 lw 2 lc rgb '#9467bd' title 'symplectic_euler unstable' noenhanced, \
       'accuracy-free-fall.dat' index 10 using 2:1 with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '#555555' title 'backward_euler' noenhanced
  unset arrow 1
  unset multiplot
}
set output
# Unstable runs (the §8 detector fired, or the state blew up) are crosses; errors above 1 m (and non-finite ones) are drawn at that cap (dashed line); errors below 1e-16 m at that floor.
