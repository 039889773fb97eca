file(REMOVE_RECURSE
  "libsc_rtl.a"
)
