"""Operating a running graph: the control endpoint the CLI talks to, its connections, doctor, the tf tree's drawing."""

__all__: list[str] = []
