1(G65 argument specification I: every letter to its local; G L N O P are not arguments)
G65 P9010 A1 B2 C3 I4 J5 K6 D7 E8 F9 H11 M13 Q17 R18 S19 T20 U21 V22 W23 X24 Y25 Z26
M30
O9010
#30 = 1
WHILE [#30 LE 26] DO1
#[100 + #30] = #[#30]
#30 = #30 + 1
END1
M99
