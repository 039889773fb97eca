# Empty dependencies file for scurve.
# This may be replaced when dependencies are built.
