"""Planners of the seed papers 001-004 behind one interface (`usvstation.planning.registry`)."""
