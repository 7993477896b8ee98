#!/usr/bin/env python3
"""Spawn turtle2 at (4, 2) and make it follow turtle1 (or ~target_frame) using tf2, at 10 Hz."""
from learning_tf2.follower import main

if __name__ == "__main__":
    main("latest")
