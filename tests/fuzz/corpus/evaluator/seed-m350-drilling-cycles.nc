0(Canned drilling cycles on the M350: a row of G81 holes, G83 pecking with the retraction of)
(parameter 224, set to 1 mm by --param, G84 tapping with a 500 ms dwell at the bottom,)
(feeding out to R and rapiding on to the initial level)
G90 G54 G00 X0 Y0 Z10
M03 S1000
G98 G81 X10 Y10 Z-3 R2 F300
X20
G99 G83 X30 Z-8 R2 Q3
G80
G00 Z10
G98 G84 X40 Z-5 R2 F200 P500
G80
M30
