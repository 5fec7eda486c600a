// error.nc runs when an alarm stops the machine (written for M350 Studio). A multi-tool setting
// (O505, #1993 = 1 while it runs) that the alarm stopped is over: the tools it set keep their
// offsets, and the next tool change must not take itself for part of a batch.
#1993 = 0
