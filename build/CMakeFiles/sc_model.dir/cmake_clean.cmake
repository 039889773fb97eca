file(REMOVE_RECURSE
  "CMakeFiles/sc_model.dir/cmodel/axis_core.cpp.o"
  "CMakeFiles/sc_model.dir/cmodel/axis_core.cpp.o.d"
  "CMakeFiles/sc_model.dir/cmodel/fixed_point.cpp.o"
  "CMakeFiles/sc_model.dir/cmodel/fixed_point.cpp.o.d"
  "CMakeFiles/sc_model.dir/cmodel/planner.cpp.o"
  "CMakeFiles/sc_model.dir/cmodel/planner.cpp.o.d"
  "CMakeFiles/sc_model.dir/cmodel/profile_exec.cpp.o"
  "CMakeFiles/sc_model.dir/cmodel/profile_exec.cpp.o.d"
  "CMakeFiles/sc_model.dir/cmodel/step_gen.cpp.o"
  "CMakeFiles/sc_model.dir/cmodel/step_gen.cpp.o.d"
  "libsc_model.a"
  "libsc_model.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/sc_model.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
