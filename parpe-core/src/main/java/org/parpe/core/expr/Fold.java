package org.parpe.core.expr;

/** Tells whether every input of a node is a constant, so the node can be folded at load. */
final class Fold {
    private Fold() {
    }

    static boolean childrenConstant(Node n) {
        if (n instanceof Nodes.Unary) {
            return c(((Nodes.Unary) n).arg);
        }
        if (n instanceof Nodes.Binary) {
            return c(((Nodes.Binary) n).left) && c(((Nodes.Binary) n).right);
        }
        if (n instanceof Nodes.And) { // and Or
            return c(((Nodes.And) n).left) && c(((Nodes.And) n).right);
        }
        if (n instanceof Nodes.If) {
            Nodes.If f = (Nodes.If) n;
            return c(f.cond) && c(f.then) && c(f.otherwise);
        }
        if (n instanceof Nodes.Func1) {
            return c(((Nodes.Func1) n).arg);
        }
        if (n instanceof Nodes.Func2) {
            return c(((Nodes.Func2) n).a) && c(((Nodes.Func2) n).b);
        }
        if (n instanceof Nodes.Sum) {
            for (Node a : ((Nodes.Sum) n).args) {
                if (!c(a)) {
                    return false;
                }
            }
            return true;
        }
        return false;
    }

    private static boolean c(Node n) {
        return n instanceof Nodes.Const;
    }
}
