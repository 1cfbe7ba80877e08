"""effect: hang
tries: a list subclass bound to eom whose iteration never ends: the sandbox encodes it after the answer's code has finished.

A loop in a student method the grader calls; the sandbox's CPU limit should end it.
"""

from lagrade.answer import *

def forever(self):
    while True:
        pass


Endless = type("Endless", (list,), {"_" + "_iter_" + "_": forever})
eom = Endless([1])
