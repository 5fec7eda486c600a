// The panel's M5 key (written for M350 Studio): the spindle stops.
M5
