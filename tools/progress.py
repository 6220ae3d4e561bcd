# SPDX-License-Identifier: GPL-2.0-or-later
"""Progress lines with an estimate of the remaining time, for the Python scripts of validation/,
bench/ and the showcase (stdout, flushed):

    p = Progress({"chute 1 rank": 3, "bed 2 ranks": 5})     # stages and their expected relative cost
    ...
    p.done("chute 1 rank")   # [progress] 1/2 chute 1 rank done after 12 s; elapsed 12 s, about 20 s to go

    p = Progress(n=30, label="rounds")                      # N equal stages
    p.done()                                                # [progress] 7/30 rounds done ...

Remaining = elapsed x (weight of the stages left) / (weight of the stages done).
"""
import sys
import time


class Progress:
    def __init__(self, weights=None, n=None, label="stages", stream=None):
        if weights is None:
            weights = {i: 1.0 for i in range(n or 1)}
        self.weights = dict(weights)
        self.total = float(sum(self.weights.values())) or 1.0
        self.n = len(self.weights)
        self.label = label
        self.k = 0
        self.wdone = 0.0
        self.t0 = self.last = time.time()
        self.stream = stream or sys.stdout

    def remaining(self):
        el = time.time() - self.t0
        return el * max(self.total - self.wdone, 0.0) / self.wdone if self.wdone > 0 else float("nan")

    def done(self, name=None):
        now = time.time()
        key = name if name in self.weights else self.k
        self.wdone += self.weights.get(key, self.total / self.n)
        self.k += 1
        what = name if name is not None else self.label
        self.stream.write("[progress] %d/%d %s done after %.0f s; elapsed %.0f s, about %.0f s to go\n"
                          % (self.k, self.n, what, now - self.last, now - self.t0, self.remaining()))
        self.stream.flush()
        self.last = now
