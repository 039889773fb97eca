
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/tb/scurve_main.cpp" "CMakeFiles/scurve.dir/tb/scurve_main.cpp.o" "gcc" "CMakeFiles/scurve.dir/tb/scurve_main.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build/CMakeFiles/sc_tb.dir/DependInfo.cmake"
  "/work/main/build/CMakeFiles/sc_rtl.dir/DependInfo.cmake"
  "/work/main/build/CMakeFiles/sc_model.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
