// 多刀固定对刀 the Probe page's multi-tool setting (written for M350 Studio): the panel lists the
// tools in #1970-#1989; O505 in slib-probe.nc changes to and sets each (#1993 = 1 during a change).
M98 P505
