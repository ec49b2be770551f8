set terminal pngcairo size 800,500
set output 'figure5.png'
set datafile separator ','
set key autotitle columnhead left top
set xlabel 'spheres'
set ylabel 'seconds per frame'
set title 'Schwarzschild, 800x600, 50 segments, 500 steps (the paper, Figure 5)'
plot 'figure5.csv' using 1:2 with linespoints title 'no acceleration', '' using 1:3 with linespoints title 'early-z + step doubling', '' using 1:4 with linespoints title 'all techniques', '' using 1:5 with linespoints title 'all, single pass', '' using 1:6 with linespoints title 'all, one fused pass a segment'
