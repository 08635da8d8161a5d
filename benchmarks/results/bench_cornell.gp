# Drawn by `vct bench` (vct bench benchmarks/sweeps/cornell.json); run `gnuplot bench_cornell.gp` in this folder to draw it again.
set terminal pngcairo size 2100,700 enhanced font 'DejaVu Sans,10'
set output "bench_cornell.png"
$engine << EOD
202.6 0.0711056 0.06987 "GI off"
760.6 0.0666806 0.0652393 "L6"
1148 0.070405 0.0690026 "L7"
2042 0.0781753 0.0762379 "light view 512"
2268 0.0777528 0.0762056 "light view 1024"
2483 0.111828 0.110582 "no bricks"
2527 0.0776219 0.0762084 "default"
2678 0.0825749 0.0814706 "lift 1.5"
2720 0.0760022 0.0746386 "cones 6"
2760 0.0970124 0.095631 "lift 0.5"
2848 0.0760524 0.0746879 "aperture 0.75"
2899 0.0714597 0.0700817 "aperture 1.25"
2956 0.0709861 0.0695202 "cones 9"
3039 0.0690591 0.067601 "step 1"
3102 0.0739205 0.0724644 "step 0.35"
3398 0.12317 0.122637 "cones 1"
3945 0.0735343 0.072176 "cones 16"
8893 0.0748084 0.0732621 "L9"
EOD
$pathtracer << EOD
34.59 0.152846 0.152266 "1"
72.21 0.106638 0.105955 "2"
150.6 0.0747809 0.0742655 "4"
287.9 0.0533364 0.0529291 "8"
529.6 0.0376246 0.0373476 "16"
1156 0.0264832 0.0262843 "32"
1408 0.0189356 0.0188115 "64"
3305 0.0134033 0.0133121 "128"
8559 0.0096764 0.00960391 "256"
EOD
$pareto << EOD
202.6 0.0711056 0.06987 "GI off"
760.6 0.0666806 0.0652393 "L6"
EOD
$paretoIndirect << EOD
202.6 0.0711056 0.06987 "GI off"
760.6 0.0666806 0.0652393 "L6"
EOD
$default << EOD
2527 0.0776219 0.0762084 "default"
EOD
set xtics ("1" 1, "2" 2, "5" 5, "10" 10, "20" 20, "50" 50, "100" 100, "200" 200, "500" 500, "1000" 1000, "2000" 2000, "5000" 5000, "10000" 10000, "20000" 20000, "50000" 50000, "100000" 100000, "200000" 200000, "500000" 500000)
noise = 0.00233982
set multiplot layout 1,3 title "cornell 320x240: error against time, vct settings and the path tracer (1 bounce, reference 4096 spp), llvmpipe (LLVM 15.0.6, 256 bits), 2026-11-21" font ',12'
set logscale xy
set grid xtics ytics mxtics mytics lc rgb '#e0e0e0'
set xlabel 'time (ms, log): vct full warm frame / path-tracer render, same CPU'
set key bottom left box opaque font ',9'
set offsets graph 0.08, graph 0.25, graph 0.1, graph 0.1
set autoscale fix
set ytics ("0.0001" 0.0001, "0.0002" 0.0002, "0.0005" 0.0005, "0.001" 0.001, "0.002" 0.002, "0.005" 0.005, "0.01" 0.01, "0.02" 0.02, "0.05" 0.05, "0.1" 0.1, "0.2" 0.2, "0.5" 0.5, "1" 1, "2" 2, "5" 5, "10" 10, "20" 20, "50" 50)
set ylabel 'RMSE of the full image vs reference (linear, log)'
set title 'full image'
plot $pathtracer using 1:2 with linespoints pt 5 ps 0.8 lw 1.5 lc rgb '#d62728' title 'path tracer (spp)', \
     $pathtracer using 1:2:(sprintf('%s spp', strcol(4))) with labels offset char 0,-0.9 font ',8' tc rgb '#d62728' notitle, \
     $pareto using 1:2 with linespoints pt 4 ps 1.9 lw 2 dt 2 lc rgb '#1f77b4' title 'Pareto front (vct)', \
     $engine using 1:2 with points pt 7 ps 1.0 lc rgb '#1f77b4' title 'vct settings', \
     $engine using 1:2:4 with labels left offset char 0.6,0.35 font ',8' notitle, \
     $default using 1:2 with points pt 6 ps 2.4 lw 2 lc rgb 'black' title 'vct default', \
     noise with lines dt 3 lc rgb '#808080' title 'reference noise (est.)'
set ytics ("0.0001" 0.0001, "0.0002" 0.0002, "0.0005" 0.0005, "0.001" 0.001, "0.002" 0.002, "0.005" 0.005, "0.01" 0.01, "0.02" 0.02, "0.05" 0.05, "0.1" 0.1, "0.2" 0.2, "0.5" 0.5, "1" 1, "2" 2, "5" 5, "10" 10, "20" 20, "50" 50)
set ylabel 'RMSE of the indirect part vs reference (linear, log)'
set title 'indirect part alone (final − direct)'
plot $pathtracer using 1:3 with linespoints pt 5 ps 0.8 lw 1.5 lc rgb '#d62728' title 'path tracer (spp)', \
     $pathtracer using 1:3:(sprintf('%s spp', strcol(4))) with labels offset char 0,-0.9 font ',8' tc rgb '#d62728' notitle, \
     $paretoIndirect using 1:3 with linespoints pt 4 ps 1.9 lw 2 dt 2 lc rgb '#1f77b4' title 'Pareto front (vct)', \
     $engine using 1:3 with points pt 7 ps 1.0 lc rgb '#1f77b4' title 'vct settings', \
     $engine using 1:3:4 with labels left offset char 0.6,0.35 font ',8' notitle, \
     $default using 1:3 with points pt 6 ps 2.4 lw 2 lc rgb 'black' title 'vct default', \
     noise with lines dt 3 lc rgb '#808080' title 'reference noise (est.)'
set offsets 0, 0, 0, 0
unset logscale y
set ytics auto
set format y '%g'
set xtics ("10" 10, "20" 20, "50" 50, "100" 100, "200" 200, "500" 500, "1000" 1000, "2000" 2000, "5000" 5000, "10000" 10000, "20000" 20000, "50000" 50000, "100000" 100000, "200000" 200000, "500000" 500000)
set xrange [155.865:16007.4]
set yrange [0.0621614:0.12769]
set key top left box opaque font ',9'
set ylabel 'RMSE of the full image vs reference (linear)'
set title 'vct points only (zoom; full image)'
plot $pareto using 1:2 with linespoints pt 4 ps 1.9 lw 2 dt 2 lc rgb '#1f77b4' title 'Pareto front (vct)', \
     $engine using 1:2 with points pt 7 ps 1.0 lc rgb '#1f77b4' notitle, \
     $engine using 1:2:4 with labels left offset char 0.6,0.35 font ',8' notitle, \
     $default using 1:2 with points pt 6 ps 2.4 lw 2 lc rgb 'black' title 'vct default', \
     $pathtracer using 1:2 with linespoints pt 5 ps 0.8 lw 1.5 lc rgb '#d62728' notitle, \
     $pathtracer using 1:2:(sprintf('%s spp', strcol(4))) with labels offset char 0,-0.9 font ',8' tc rgb '#d62728' notitle
unset multiplot
