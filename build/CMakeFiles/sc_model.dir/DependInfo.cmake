
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/cmodel/axis_core.cpp" "CMakeFiles/sc_model.dir/cmodel/axis_core.cpp.o" "gcc" "CMakeFiles/sc_model.dir/cmodel/axis_core.cpp.o.d"
  "/work/main/cmodel/fixed_point.cpp" "CMakeFiles/sc_model.dir/cmodel/fixed_point.cpp.o" "gcc" "CMakeFiles/sc_model.dir/cmodel/fixed_point.cpp.o.d"
  "/work/main/cmodel/planner.cpp" "CMakeFiles/sc_model.dir/cmodel/planner.cpp.o" "gcc" "CMakeFiles/sc_model.dir/cmodel/planner.cpp.o.d"
  "/work/main/cmodel/profile_exec.cpp" "CMakeFiles/sc_model.dir/cmodel/profile_exec.cpp.o" "gcc" "CMakeFiles/sc_model.dir/cmodel/profile_exec.cpp.o.d"
  "/work/main/cmodel/step_gen.cpp" "CMakeFiles/sc_model.dir/cmodel/step_gen.cpp.o" "gcc" "CMakeFiles/sc_model.dir/cmodel/step_gen.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
