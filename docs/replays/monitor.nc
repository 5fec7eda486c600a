(a pocket outline for the Monitor screenshot: the program window follows the run)
G90 G54 G17 G21
M3 S12000
G0 X0 Y0
G0 Z5
G1 Z-1 F600
G1 X40 F1500
G1 Y20
G1 X0
G1 Y0
G1 X5 Y5
G1 X35
G1 Y15
G1 X5
G1 Y5
G0 Z5
M5
M30
