// 回机械原点 Go Home, Y only (written for M350 Studio): the firmware's single-axis homing O501.
M98 P501 X1
