"""Altimeter-aided attitude paper (slug ``altimeter_attitude``): batched estimators."""
