"""The shipped graph files, one per exercise: `python -m actors.run turtlebot` runs turtlebot.toml from here."""
