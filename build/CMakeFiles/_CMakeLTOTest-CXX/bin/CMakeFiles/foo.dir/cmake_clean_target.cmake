file(REMOVE_RECURSE
  "libfoo.a"
)
