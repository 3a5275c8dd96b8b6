"""The 3D (x, y, t) view served by viser."""
