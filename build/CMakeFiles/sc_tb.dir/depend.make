# Empty dependencies file for sc_tb.
# This may be replaced when dependencies are built.
