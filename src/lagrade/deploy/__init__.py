"""Deploying lagrade on a course platform: the Gradescope autograder zip, the PrairieLearn grader.

Above the bulk layer: these modules package what ``lagrade.bulk`` grades and exports.
"""
