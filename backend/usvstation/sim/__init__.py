"""The simulated boat: the boat side of usv-link (boat.py) driving a Vehicle (vehicle.py)."""
