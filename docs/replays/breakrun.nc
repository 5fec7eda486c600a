(断点加工 Break Run screenshot: a short square, paused in line 5)
G90 G54 G0 X10 Y10 Z5
M3 S8000
G1 Z-1 F600
G91 X30
Y30
X-30
G90 Y10
G0 Z10
M5
M30
