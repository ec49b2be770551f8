set terminal pngcairo size 900,600
set output 'pareto.png'
set logscale xy
set xlabel 'seconds per frame'
set ylabel 'exit direction error, p99 (rad)'
set title 'Pareto fronts: speed against error (front configurations only)'
set key outside right
plot 'pareto.dat' index 0 with linespoints title 'schwarzschild sky', 'pareto.dat' index 1 with linespoints title 'schwarzschild', 'pareto.dat' index 2 with linespoints title 'neutron_star', 'pareto.dat' index 3 with linespoints title 'lorenz', 'pareto.dat' index 4 with linespoints title 'rossler', 'pareto.dat' index 5 with linespoints title 'potential', 'pareto.dat' index 6 with linespoints title 'refraction'
