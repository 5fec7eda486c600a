1(save the distance mode from #4003, change it, restore it with G#199)
G91
#199 = #4003
G90
G00 X10
G#199 X5
#198 = #4003
#197 = #4001
#196 = #4006
G#198
M30
