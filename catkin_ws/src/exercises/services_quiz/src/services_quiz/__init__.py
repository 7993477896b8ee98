"""services_quiz: the /turn request as a velocity plan (plain Python)."""
