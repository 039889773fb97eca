# Empty compiler generated dependencies file for boo.
# This may be replaced when dependencies are built.
