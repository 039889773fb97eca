file(REMOVE_RECURSE
  "CMakeFiles/sc_tb.dir/tb/lockstep.cpp.o"
  "CMakeFiles/sc_tb.dir/tb/lockstep.cpp.o.d"
  "CMakeFiles/sc_tb.dir/tb/pin_monitor.cpp.o"
  "CMakeFiles/sc_tb.dir/tb/pin_monitor.cpp.o.d"
  "CMakeFiles/sc_tb.dir/tb/report.cpp.o"
  "CMakeFiles/sc_tb.dir/tb/report.cpp.o.d"
  "CMakeFiles/sc_tb.dir/tb/sim_run.cpp.o"
  "CMakeFiles/sc_tb.dir/tb/sim_run.cpp.o.d"
  "libsc_tb.a"
  "libsc_tb.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/sc_tb.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
