"""The window: turtle sprites over the pen canvas, and whether a display exists."""
