"""Technology objects of S7-Technology V4.1: axes, external encoders, cams, output cams, cam tracks,
measuring inputs, their technology DBs and the tables of their parameters and ErrorIDs."""
