// Placeholder translation unit for an area that has only headers so far.
