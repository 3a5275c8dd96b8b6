"""The boat link: usv-link 2 (MAVLink 2 dialect, protocol/usv_recovery.xml), the pymavlink
codec with signing, sans-IO station state machines, transports and the async BoatLink.

Specification: protocol/README.md; layers: docs/link.md.
"""
