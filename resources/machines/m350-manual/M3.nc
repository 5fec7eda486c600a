// The panel's M3 key (written for M350 Studio): the spindle at the default speed, param 85 (#585).
M3 S#585
