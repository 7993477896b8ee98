#!/usr/bin/env python3
"""Time travel done right: follow where turtle1 was 5 s ago, relative to turtle2 now (lookup_transform_full)."""
from learning_tf2.follower import main

if __name__ == "__main__":
    main("now")
