; An inductive assumption for producer_consumer.bip: every item made was received, except the
; one waiting at the producer. `smcbip prove` checks that it holds initially and that every
; transition of the net keeps it (given the component and trap invariants) before using it.
(assert (= ROOT.p.x (+ ROOT.c.y (ite ROOT.p.full 1 0))))
