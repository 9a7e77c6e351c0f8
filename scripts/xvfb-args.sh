# Sourced by the ParaView tests and benchmarks: the Xvfb server arguments for xvfb-run -s.
# -noreset: without it Xvfb resets when its last client disconnects, and a rank that connects
# during the reset is refused ("bad X server connection"; ParaView's first rank opens and
# closes a probe window while the others start): 3 of 20 8-rank pvbatch starts failed so
# without it, 0 of 30 with it (bench/paraview/startup_hang.sh, --xvfb-reset to compare).
# XVFB_SCREEN: the screen, WxHxDEPTH.
FLOWSURF_XVFB_ARGS="-screen 0 ${XVFB_SCREEN:-1280x1024x24} -noreset"
