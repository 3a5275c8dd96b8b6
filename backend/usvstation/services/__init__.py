"""Station services: plan jobs, live fan-out, missions, telemetry ingest."""
