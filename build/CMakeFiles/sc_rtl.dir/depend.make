# Empty dependencies file for sc_rtl.
# This may be replaced when dependencies are built.
