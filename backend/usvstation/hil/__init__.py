"""Hardware in the loop: the boat's firmware binary (protocol/c/boat, `make qemu`) in QEMU's
emulated Cortex-M3, its navigation and thrust bridged to the vessel model (`usv-station hil`)."""
