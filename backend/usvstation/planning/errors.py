"""Planning errors, importable without NumPy or SciPy (the server unpickles them)."""


class NoFeasiblePlan(RuntimeError):
    """No plan meets every hard constraint; the message gives the reason."""
