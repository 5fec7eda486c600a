(IF ... THEN, and AND / OR written arithmetically)
#1=1
#2=5
IF [#1==1] THEN #100=5
IF [#1==2] THEN #101=7
IF [#1==1]*[#2<3] GOTO10   //AND: false
#102=1
N10
IF [#1==1]+[#2<3] GOTO20   //OR: true
#103=1
N20
IF [#1 EQ 1] THEN #104=[#2*2]
M30
