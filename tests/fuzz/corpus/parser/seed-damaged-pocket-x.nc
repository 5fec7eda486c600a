(the manual's damaged pocket move: X[#1330+#1300-1] adds a tool number to a pocket X)
G53 Z#1306 F#1312
G53 Y#1309 F#1311
G53 X[#1330+#1300-1] F#1311
M30
