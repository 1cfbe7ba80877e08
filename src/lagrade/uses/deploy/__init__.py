"""Deploying lagrade on a course platform: the Gradescope autograder zip, the PrairieLearn grader.

Above the bulk layer: these modules package what ``lagrade.uses.bulk`` grades and exports.
"""
