# Empty dependencies file for sc_model.
# This may be replaced when dependencies are built.
