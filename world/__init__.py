"""A top-down 2D pymunk world with differential-drive TurtleBots, as actors nodes."""
