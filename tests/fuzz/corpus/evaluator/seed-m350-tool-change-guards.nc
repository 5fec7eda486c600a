0(O20000's exits that need no motion; tool 1 is in the spindle)
T37   //beyond the magazine (16) and the virtual tools T17-T36 (param 803): nothing happens
T1    //already in the spindle: nothing happens
T0    //target 0: message, no change
M30
