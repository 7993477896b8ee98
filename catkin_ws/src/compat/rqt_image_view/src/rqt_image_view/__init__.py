"""rqt_image_view: the course's image viewer command through Debian's image_view (see main)."""
