// slib-m.nc of the default machine: M-code handlers (O10000+n), written for M350 Studio.
// Each actuator and each sensor wait finds its port on the IO page, in its parameter triple
// (parameter N = pin, N+1 = enable, N+2 = active level; parameter N is variable #(N+500)):
//   outputs  750 tool release/clamp (M154/M155)   753 magazine out/in (M152/M153)
//            762 dust cover open/close (M150/M151)
//   inputs   620 spindle stopped (M300)   623 tool released (M301)   626 tool clamped (M302)
//            629 magazine out (M303)      697 magazine in (M304)     632 dust cover (M305/M306)
// OUTk is #[1552+k-1] and INk is #[1520+k-1]. A function that is not enabled, or has no pin, is
// skipped: nothing is driven and nothing is waited for. A wait polls every 10 ms; if the sensor
// never comes, the simulator's sensor watchdog stops the run naming the input.

O10150(M150 除尘罩打开 dust cover open)
IF [#1263 == 0] + [#1262 < 1] GOTO1
#[1552+#1262-1] = #1264
N1 M99

O10151(M151 除尘罩关闭 dust cover close)
IF [#1263 == 0] + [#1262 < 1] GOTO1
#[1552+#1262-1] = 1 - #1264
N1 M99

O10152(M152 刀库推出 magazine out)
IF [#1254 == 0] + [#1253 < 1] GOTO1
#[1552+#1253-1] = #1255
N1 M99

O10153(M153 刀库收回 magazine in)
IF [#1254 == 0] + [#1253 < 1] GOTO1
#[1552+#1253-1] = 1 - #1255
N1 M99

O10154(M154 松刀 tool release)
IF [#1251 == 0] + [#1250 < 1] GOTO1
#[1552+#1250-1] = #1252
N1 M99

O10155(M155 紧刀 tool clamp)
IF [#1251 == 0] + [#1250 < 1] GOTO1
#[1552+#1250-1] = 1 - #1252
N1 M99

O10300(M300 等待主轴停止 wait for the spindle stopped signal)
IF [#1121 == 0] + [#1120 < 1] GOTO1
WHILE [#[1520+#1120-1] NE #1122] DO1
G04 P10
END1
N1 M99

O10301(M301 等待刀具松开 wait for tool released)
IF [#1124 == 0] + [#1123 < 1] GOTO1
WHILE [#[1520+#1123-1] NE #1125] DO1
G04 P10
END1
N1 M99

O10302(M302 等待刀具锁紧 wait for tool clamped)
IF [#1127 == 0] + [#1126 < 1] GOTO1
WHILE [#[1520+#1126-1] NE #1128] DO1
G04 P10
END1
N1 M99

O10303(M303 等待刀库推出 wait for magazine out)
IF [#1130 == 0] + [#1129 < 1] GOTO1
WHILE [#[1520+#1129-1] NE #1131] DO1
G04 P10
END1
N1 M99

O10304(M304 等待刀库收回 wait for magazine in)
IF [#1198 == 0] + [#1197 < 1] GOTO1
WHILE [#[1520+#1197-1] NE #1199] DO1
G04 P10
END1
N1 M99

O10305(M305 等待除尘罩打开 wait for the dust cover open)
IF [#1133 == 0] + [#1132 < 1] GOTO1
WHILE [#[1520+#1132-1] NE #1134] DO1
G04 P10
END1
N1 M99

O10306(M306 等待除尘罩关闭 wait for the dust cover closed)
IF [#1133 == 0] + [#1132 < 1] GOTO1
WHILE [#[1520+#1132-1] NE [1 - #1134]] DO1
G04 P10
END1
N1 M99

// 多工序 multi-process heads: M168/M170/M172/M174 lower head 1-4 (cylinder open), M169/M171/M173/M175
// raise it, on the outputs of params 777, 780, 783, 786.
O10168(M168 多工序气缸1打开 head 1 down)
IF [#1278 == 0] + [#1277 < 1] GOTO1
#[1552+#1277-1] = #1279
N1 M99

O10169(M169 多工序气缸1关闭 head 1 up)
IF [#1278 == 0] + [#1277 < 1] GOTO1
#[1552+#1277-1] = 1 - #1279
N1 M99

O10170(M170 多工序气缸2打开 head 2 down)
IF [#1281 == 0] + [#1280 < 1] GOTO1
#[1552+#1280-1] = #1282
N1 M99

O10171(M171 多工序气缸2关闭 head 2 up)
IF [#1281 == 0] + [#1280 < 1] GOTO1
#[1552+#1280-1] = 1 - #1282
N1 M99

O10172(M172 多工序气缸3打开 head 3 down)
IF [#1284 == 0] + [#1283 < 1] GOTO1
#[1552+#1283-1] = #1285
N1 M99

O10173(M173 多工序气缸3关闭 head 3 up)
IF [#1284 == 0] + [#1283 < 1] GOTO1
#[1552+#1283-1] = 1 - #1285
N1 M99

O10174(M174 多工序气缸4打开 head 4 down)
IF [#1287 == 0] + [#1286 < 1] GOTO1
#[1552+#1286-1] = #1288
N1 M99

O10175(M175 多工序气缸4关闭 head 4 up)
IF [#1287 == 0] + [#1286 < 1] GOTO1
#[1552+#1286-1] = 1 - #1288
N1 M99
