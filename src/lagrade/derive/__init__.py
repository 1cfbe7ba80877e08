"""The reference derivation: Lagrange's equations, momenta, H and Hamilton's equations from the
scene; the effects a scene declares and what they may use; the signed reference cache.
"""
