# Empty custom commands generated dependencies file for sc_params.
# This may be replaced when dependencies are built.
