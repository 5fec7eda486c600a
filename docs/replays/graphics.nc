(图形显示: a tool change, then a pocket outline with arcs; the screenshot is taken mid-run)
G90 G54 G17 G21
T3
M3 S12000
G0 X0 Y0
G0 Z5
G1 Z-2 F600
G1 X60 F3000
G3 X80 Y20 I0 J20
G1 Y50
G3 X60 Y70 I-20 J0
G1 X0
G1 Y0
G0 Z5
G0 X20 Y20
G1 Z-2 F600
G2 X20 Y20 I20 J15 F3000
G0 Z30
M5
M30
