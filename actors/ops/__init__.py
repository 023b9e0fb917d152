"""Operating a running graph: the control endpoint the CLI talks to, its connections, and doctor."""

__all__: list[str] = []
