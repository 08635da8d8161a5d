# Drawn by `vct bench` (vct bench benchmarks/sweeps/sponza.json); run `gnuplot bench_sponza.gp` in this folder to draw it again.
set terminal pngcairo size 2100,700 enhanced font 'DejaVu Sans,10'
set output "bench_sponza.png"
$engine << EOD
312.5 0.0434897 0.0314698 "GI off"
1860 0.0376188 0.021343 "L7"
2409 0.0400906 0.0258831 "L6"
2600 0.0583057 0.0209204 "light view 512"
2631 0.0426971 0.0209301 "light view 1024"
2842 0.0471651 0.0365568 "cones 1"
2856 0.0374887 0.0211634 "aperture 1.25"
2937 0.0366682 0.0188949 "cones 9"
2940 0.0373399 0.0205967 "aperture 0.75"
2942 0.0373128 0.0210915 "step 1"
2986 0.0372581 0.0207789 "step 0.35"
3030 0.0364598 0.0199693 "no bricks"
3189 0.0365134 0.0182052 "cones 16"
3339 0.0373749 0.0209624 "default"
8334 0.0375573 0.0210496 "L9"
EOD
$pathtracer << EOD
50.36 0.100817 0.0784584 "1"
102.2 0.0738977 0.0558267 "2"
202.2 0.0538235 0.0397779 "4"
404.3 0.0381158 0.0280854 "8"
785.3 0.0269262 0.0198476 "16"
1514 0.0190433 0.0141768 "32"
3251 0.0136022 0.0100257 "64"
6699 0.00987063 0.00723786 "128"
EOD
$pareto << EOD
312.5 0.0434897 0.0314698 "GI off"
1860 0.0376188 0.021343 "L7"
2856 0.0374887 0.0211634 "aperture 1.25"
2937 0.0366682 0.0188949 "cones 9"
3030 0.0364598 0.0199693 "no bricks"
EOD
$paretoIndirect << EOD
312.5 0.0434897 0.0314698 "GI off"
1860 0.0376188 0.021343 "L7"
2600 0.0583057 0.0209204 "light view 512"
2937 0.0366682 0.0188949 "cones 9"
3189 0.0365134 0.0182052 "cones 16"
EOD
$default << EOD
3339 0.0373749 0.0209624 "default"
EOD
set xtics ("1" 1, "2" 2, "5" 5, "10" 10, "20" 20, "50" 50, "100" 100, "200" 200, "500" 500, "1000" 1000, "2000" 2000, "5000" 5000, "10000" 10000, "20000" 20000, "50000" 50000, "100000" 100000, "200000" 200000, "500000" 500000)
noise = 0.00238288
set multiplot layout 1,3 title "sponza 320x180: error against time, vct settings and the path tracer (1 bounce, reference 2048 spp), llvmpipe (LLVM 15.0.6, 256 bits), 2026-11-21" font ',12'
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
set ytics ("0.0001" 0.0001, "0.0002" 0.0002, "0.0005" 0.0005, "0.001" 0.001, "0.002" 0.002, "0.005" 0.005, "0.01" 0.01, "0.02" 0.02, "0.05" 0.05, "0.1" 0.1, "0.2" 0.2, "0.5" 0.5, "1" 1, "2" 2, "5" 5)
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
set xrange [240.397:15000.6]
set yrange [0.0347122:0.0600534]
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
