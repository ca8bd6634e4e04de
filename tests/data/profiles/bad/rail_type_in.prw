! Bad-input fixture (see README.md): SIMPACK rail crown R300, z down
header.begin
  version = 1
  type    = 0     ! 0 = rail, 1 = wheel
header.end
spline.begin
  units.len.f = 1000.
  units.ang.f = 1.
  point.begin
  -11.000000  0.201734
  -9.000000  0.135030
  -7.000000  0.081678
  -5.000000  0.041670
  -3.000000  0.015000
  -1.000000  0.001667
  1.000000  0.001667
  3.000000  0.015000
  5.000000  0.041670
  7.000000  0.081678
  9.000000  0.135030
  11.000000  0.201734
  point.end
spline.end
