// The panel's M4 key (written for M350 Studio): the spindle at the default speed, param 85 (#585).
M4 S#585
