// 回工件原点 Go Work Zero (written for M350 Studio): Z up to the machine's top (G53 Z0) first, clear
// of the work and of any magazine, then X and Y over to work zero, then Z down to it.
G90 G53 G00 Z0
G00 X0 Y0
G00 Z0
