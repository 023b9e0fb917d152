"""What the runtime keeps around its nodes: the supervisor (restart policy) and the read-only graph view."""

__all__: list[str] = []
