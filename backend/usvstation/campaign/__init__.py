"""Campaigns: many planning episodes (planners x families x seeds x disturbances), pool or Ray."""
