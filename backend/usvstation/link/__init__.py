"""The boat link: usv-link codec, sans-IO station protocol, transports and the async BoatLink.

Wire format: protocol/README.md (generated parts from protocol/messages.toml).
"""
