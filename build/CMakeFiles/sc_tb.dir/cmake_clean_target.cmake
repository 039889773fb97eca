file(REMOVE_RECURSE
  "libsc_tb.a"
)
