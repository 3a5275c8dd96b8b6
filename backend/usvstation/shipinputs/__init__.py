"""Ship inputs: NMEA 0183 own-ship and ARPA sentences, and AIS, from a ship's network."""
