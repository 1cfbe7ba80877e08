"""Evaluating and compiling expressions for batches of states, and the environment lagrade's
own processes start with (one BLAS thread).
"""
