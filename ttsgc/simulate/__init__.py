"""Running scenes in SUMO: the network (netconvert of the scene's OpenDRIVE map)."""
