# Formal proofs (scripts/formal.py, docs/formal.md): one test per property
# group, formal.<group>, and one that runs the group against a deliberately
# broken copy of its module and passes only when the proof fails there,
# formal.<group>_fails_when_broken. Label `formal`. The default suite runs
# the proofs (Yices: under 15 s each) but not the broken variants, which
# show that each proof can fail and change only with the property or the
# module: they carry `extended` (CI runs them on every change), as do both
# tests of the two groups whose induction step takes minutes (the step
# generator's queue and drain bounds, z3: about 2.5 min each).
set(SC_FORMAL_FAST
  step_gen_pulse_timing step_gen_dir_timing step_gen_count
  quad_decoder_count quad_decoder_illegal quad_decoder_filter
  axi_regs_handshake axi_regs_response axi_regs_decode axi_regs_decode_axis axi_regs_pulse_time
  uart_bridge_frames uart_bridge_crc uart_bridge_crc8
  exec_steps exec_abort exec_continuity exec_soft stop_gen_limits
  core_done core_abort core_limits core_rate multi_sync_start)
set(SC_FORMAL_SLOW step_gen_overrun step_gen_drain)

foreach(group IN LISTS SC_FORMAL_FAST SC_FORMAL_SLOW)
  set(cmd ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/formal.py --group ${group}
          --build-dir ${CMAKE_BINARY_DIR}/formal)
  add_test(NAME formal.${group} COMMAND ${cmd})
  add_test(NAME formal.${group}_fails_when_broken COMMAND ${cmd} --broken)
  if(group IN_LIST SC_FORMAL_SLOW)
    set(labels "formal;extended")
    set(timeout 900)
  else()
    set(labels formal)
    set(timeout 300)
  endif()
  set_tests_properties(formal.${group} PROPERTIES LABELS "${labels}" TIMEOUT ${timeout})
  set_tests_properties(formal.${group}_fails_when_broken PROPERTIES LABELS "formal;extended" TIMEOUT ${timeout})
endforeach()
