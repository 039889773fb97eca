file(REMOVE_RECURSE
  "CMakeFiles/scurve.dir/tb/scurve_main.cpp.o"
  "CMakeFiles/scurve.dir/tb/scurve_main.cpp.o.d"
  "bin/scurve"
  "bin/scurve.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/scurve.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
