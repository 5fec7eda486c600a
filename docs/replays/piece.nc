(a short piece for the 加工统计 screenshot)
G90 G54 G0 X0 Y0
G1 X40 F3000
G1 Y20
G1 X0
G1 Y0
M30
