; True in every reachable state of producer_consumer.bip, but not inductive by itself
; (assume_not_inductive_refused.mtl).
(assert (<= ROOT.c.y ROOT.p.x))
