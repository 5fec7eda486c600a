(The M350 manual's test program: three tool changes, each followed by a move)
T1          //1号刀 tool 1
M03 S12000  //开主轴 spindle on
G01 X0Y0 F3000 //T1 轨迹代码
M5          //关主轴 spindle off
T2          //2号刀
M03 S12000
G01 X0Y0
M5
T3          //3号刀
M03 S12000
G01 X0Y0
M5
M30
