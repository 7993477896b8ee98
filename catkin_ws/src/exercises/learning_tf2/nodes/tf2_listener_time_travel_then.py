#!/usr/bin/env python3
"""Time travel, first try: follow where turtle1 was 5 s ago, relative to where turtle2 was 5 s ago."""
from learning_tf2.follower import main

if __name__ == "__main__":
    main("then")
