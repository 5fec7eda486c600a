(M350 functions: angles in degrees, ATAN[y,x] from -180 to 180)
#1=ABS[-2.5]
#2=SQRT[16]
#3=ROUND[2.5]
#4=ROUND[-2.5]
#5=FIX[-2.7]
#6=FUP[2.1]
#7=FUP[-2.1]
#8=SIN[30]
#9=COS[60]
#10=TAN[45]
#11=ATAN[1,1]
#12=ATAN[-1,-1]
#13=ATAN[1,-1]
#14=2+3*4-[1+1]/4
#15=-#2+1
M30
