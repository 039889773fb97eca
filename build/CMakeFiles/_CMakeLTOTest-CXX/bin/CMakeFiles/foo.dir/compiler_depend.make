# Empty compiler generated dependencies file for foo.
# This may be replaced when dependencies are built.
