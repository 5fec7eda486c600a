(GOTO to a label computed at run time)
#1=2
GOTO[#1*10]
#100=1
N10 #100=10
GOTO30
N20 #100=20
N30 #101=#100
#2=40
GOTO#2
#102=1
N40 M30
