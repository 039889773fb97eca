file(REMOVE_RECURSE
  "CMakeFiles/bench_sim.dir/tb/bench_sim.cpp.o"
  "CMakeFiles/bench_sim.dir/tb/bench_sim.cpp.o.d"
  "bin/bench_sim"
  "bin/bench_sim.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/bench_sim.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
