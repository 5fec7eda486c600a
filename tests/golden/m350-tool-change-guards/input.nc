(O20000's exits that need no motion; tool 1 is in the spindle)
T17   //above the magazine capacity (#1301 = 16): nothing happens
T1    //already in the spindle: nothing happens
T0    //target 0: message, no change
M30
