# ctest helper: install the host library into WORK_DIR/prefix, then build and
# run examples/consumer against it with find_package(scurve).
#   cmake -DBUILD_DIR=.. -DWORK_DIR=.. -DCONSUMER_DIR=.. -DCONFIG=.. -DCXX=.. -P install_check.cmake
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
set(cfg_args)
if(CONFIG)
  set(cfg_args --config "${CONFIG}")
endif()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok")
  set(last_out "${out}" PARENT_SCOPE)
endfunction()

run("install" ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}" ${cfg_args})
foreach(f include/scurve/planner.h include/scurve/hw/params.h include/scurve/hw/regmap.h
          lib/cmake/scurve/scurveConfig.cmake lib/cmake/scurve/scurveConfigVersion.cmake)
  if(NOT EXISTS "${prefix}/${f}")
    message(FATAL_ERROR "install: ${f} missing")
  endif()
endforeach()
run("configure consumer" ${CMAKE_COMMAND} -S "${CONSUMER_DIR}" -B "${WORK_DIR}/consumer"
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_BUILD_TYPE=Release)
run("build consumer" ${CMAKE_COMMAND} --build "${WORK_DIR}/consumer")
run("run consumer" "${WORK_DIR}/consumer/scurve_consumer")
message(STATUS "${last_out}")
if(NOT last_out MATCHES "steps 30000 of 30000")
  message(FATAL_ERROR "consumer output unexpected: ${last_out}")
endif()
