1(Absolute G90 and incremental G91 positioning with G0 and G1.)
(Every number has a decimal point: FANUC reads X10 as 10 least increments.)
G17 G21 G90
G0 X10. Y20. Z5.
G1 X30. Y25. Z-2. F500.
G91
G1 X5. Y-10.
G0 Z10.
G1 X-2.5 Y1.25 Z-3.75
(axes not written stay where they are)
Y4.
G90 G0 X0 Y0
G91 G0 X1.
Z-1.
G90 X7. Y8. Z9.
G91 G1 X0.0001 Y-0.0001 Z0
G90 G1 X-12.3456 Y65.4321 Z-0.5
M2
