"""Path planning: the IGA of paper 000 section 3.2 and its metrics (pure, NumPy).

Entry point: `usvstation.planning.plan.plan_scenario`.
"""
