(图形显示: T1 driven sideways into pocket 4, which holds T4: the crash is marked where it happened)
G53 G0 Z0
G53 G0 X230 Y60
G53 G0 Z-80
G53 G1 Y5 F2000
M30
