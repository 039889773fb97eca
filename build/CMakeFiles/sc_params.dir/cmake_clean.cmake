file(REMOVE_RECURSE
  "CMakeFiles/sc_params"
  "generated/sc_params.h"
)

# Per-language clean rules from dependency scanning.
foreach(lang )
  include(CMakeFiles/sc_params.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
