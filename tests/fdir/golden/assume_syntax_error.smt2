; A parenthesis too many (assume_syntax_error.mtl).
(assert (<= ROOT.c.y ROOT.p.x))
(assert (>= ROOT.c.y 0)))))
