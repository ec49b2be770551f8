set terminal pngcairo size 900,600 noenhanced
set output 'pareto.png'
set logscale xy
set format x '%g'
set format y '%.0e'
set xlabel 'seconds per frame'
set ylabel 'exit direction error, p99 (rad)'
set title 'Speed against error'
set key outside right
plot 'pareto.dat' index 0 with points lc 1 pt 7 title 'schwarzschild sky', '' index 1 with steps lc 1 notitle, 'pareto.dat' index 2 with points lc 2 pt 7 title 'schwarzschild', '' index 3 with steps lc 2 notitle, 'pareto.dat' index 4 with points lc 3 pt 7 title 'neutron_star', '' index 5 with steps lc 3 notitle, 'pareto.dat' index 6 with points lc 4 pt 7 title 'lorenz', '' index 7 with steps lc 4 notitle, 'pareto.dat' index 8 with points lc 5 pt 7 title 'rossler', '' index 9 with steps lc 5 notitle, 'pareto.dat' index 10 with points lc 6 pt 7 title 'potential', '' index 11 with steps lc 6 notitle, 'pareto.dat' index 12 with points lc 7 pt 7 title 'refraction', '' index 13 with steps lc 7 notitle
