; Inductive assumptions for train_gate.bip (`smcbip prove ... --assume train_gate.smt2`): with
; them the invariants prove the safety query that otherwise the exhaustive search decides.
; The controller counts the trains between their approach and their exit.
(define-fun in ((near Bool) (crossing Bool)) Int (ite (or near crossing) 1 0))
(assert (= ROOT.controller.inside
           (+ (in ROOT.t0.near ROOT.t0.crossing) (in ROOT.t1.near ROOT.t1.crossing)
              (in ROOT.t2.near ROOT.t2.crossing))))
; A train crosses only while the controller guards the crossing.
(assert (=> (or ROOT.t0.crossing ROOT.t1.crossing ROOT.t2.crossing) ROOT.controller.guarding))
