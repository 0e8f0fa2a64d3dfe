"""S7-Technology V4.1 (CPU 31xT): technology objects and the FB 401 ... FB 463 motion instructions."""
