"""amcl's particle filter: likelihood-field laser model, diff-drive odometry model, KLD resampling."""
