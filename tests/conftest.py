"""Test configuration.

Hypothesis runs derandomized by default so that CI is reproducible; explore with random inputs and more
examples with ``pytest --hypothesis-profile=explore``.
"""
from hypothesis import HealthCheck, settings

settings.register_profile("ci", derandomize=True, deadline=None, print_blob=True)
settings.register_profile("explore", max_examples=1500, deadline=None, print_blob=True,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile("ci")
