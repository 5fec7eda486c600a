(刀具寿命 Tool Life screenshot: group 1 by uses, group 2 by minutes)
(T6 cuts past its minute, the next T102 brings in its sister T7)
G10 L3
P1 L5 Q1
T3 H3 D13
T4 H4 D14
P2 L1 Q2
T6 H6 D16
T7 H7 D17
T8 H8 D18
G11
T101
T102
G90 G54 G0 X10 Y10
G91 G1 X50 F300
X-50
X50
X-50
X50
X-50
X50
T102
G1 X-50 F300
M30
