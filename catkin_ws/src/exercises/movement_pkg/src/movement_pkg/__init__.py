"""movement_pkg: the /movement and /move requests as velocity plans (plain Python)."""
