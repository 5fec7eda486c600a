(G68: the program turned about a point in the XY plane, side by side with LinuxCNC's rotated)
(G54, G10 L2 R, in g68.ngc; a centre away from work zero is a G52 shift there.)
(Each rotation starts with an absolute move naming X and Y: until one, a FANUC turns about where)
(the tool stood at G68 and LinuxCNC about the rotated system's origin.)
G17 G21 G90
G10 L2 P1 X100. Y50. Z-20.
G54 G0 X0 Y0 Z5.
(30 degrees about work zero: lines, incremental moves, arcs by I J and by R)
G68 X0 Y0 R30.
G0 X10. Y0
G1 Z-2. F300.
G1 X40. Y0 F600.
G1 Y20.
G91 G1 X-10. Y0
G90 G3 X10. Y20. I-10. J0
G2 X20. Y10. R10.
G91 G2 X10. Y-10. I10. J0
G90 G1 Z5.
G69
G0 X0 Y0
(-45 degrees about X20 Y10: a drilling pattern)
G68 X20. Y10. R-45.
G0 X20. Y10.
G98 G81 X30. Y10. Z-5. R2. F200.
X40.
Y20.
G80
G69
G90 G0 X0 Y0 Z5.
M2
