"""Comparing an answer with the reference: symbolic proofs, equation systems, the sampled states,
certified rejections, and trajectories integrated by the one DOP853 from the scene's model."""
