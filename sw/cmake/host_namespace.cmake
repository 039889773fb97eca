# cmake -DIN=<generated.h> -DOUT=<host header> -P host_namespace.cmake
# The generators (scripts/gen_params.py, scripts/gen_regmap.py) write the
# hardware model's namespace `sc`; the host library carries the same
# constants in `scurve::hw`, so a program can include both views.
file(READ "${IN}" text)
string(REGEX REPLACE "namespace sc([ :{])" "namespace scurve::hw\\1" text "${text}")
string(REGEX REPLACE "// namespace sc\n" "// namespace scurve::hw\n" text "${text}")
string(REGEX REPLACE "// namespace sc::" "// namespace scurve::hw::" text "${text}")
string(REPLACE "#include \"sc_params.h\"" "#include \"scurve/hw/params.h\"" text "${text}")
string(REPLACE "#include \"sc_regmap.h\"" "#include \"scurve/hw/regmap.h\"" text "${text}")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
  if(old STREQUAL text)
    return()
  endif()
endif()
file(WRITE "${OUT}" "${text}")
