file(REMOVE_RECURSE
  "libsc_model.a"
)
