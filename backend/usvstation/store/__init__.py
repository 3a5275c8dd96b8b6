"""SQLite storage of telemetry, runs, plans and missions."""
