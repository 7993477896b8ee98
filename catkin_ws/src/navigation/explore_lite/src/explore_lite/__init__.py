"""explore_lite's node (`explore_node`) and its frontier markers (`markers`), over lab_nav.exploration."""
