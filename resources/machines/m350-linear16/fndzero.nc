// 回机械原点 Go Home, all axes (written for M350 Studio): Z first, clear of the work, then X and Y,
// each by the firmware's single-axis homing O501 (M98 P501 X<axis>: 0 X, 1 Y, 2 Z).
M98 P501 X2
M98 P501 X0
M98 P501 X1
