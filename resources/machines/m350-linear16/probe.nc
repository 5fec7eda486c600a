// 固定对刀 the Probe page's fixed tool setting (written for M350 Studio): the panel sets #1502
// (1 first setting, 2 again after a change); O502 in slib-probe.nc does the setting.
M98 P502
