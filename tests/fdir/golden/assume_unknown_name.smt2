; The producer has no datum count (assume_unknown_name.mtl).
(assert (<= ROOT.c.y ROOT.p.count))
