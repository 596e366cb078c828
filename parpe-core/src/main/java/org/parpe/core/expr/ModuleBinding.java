package org.parpe.core.expr;

import java.util.List;
import org.parpe.core.lang.Vocabulary;

/**
 * Partial evaluation of a tree for one module of one group: {@code $index}, {@code $count} and
 * {@code $id} become numbers and every part that then has only numbers for inputs is folded
 * the way loading folds constants ({@link ExprCompiler#fold}: a part whose evaluation fails
 * stays, to fail at run time as before). The scheduler binds each target once per module
 * when a run is built, so {@code 2*cos(pi*$index/$count)} costs nothing per tick (issue 36).
 * The folded values are those the unbound tree computes, bit for bit: the same operations on
 * the same numbers. Parts left as they were are shared with the original tree.
 */
final class ModuleBinding extends ExprTree.ByLeaf<Node> {
    private final double index;
    private final double count;
    private final double id;
    /** The node being visited (the visitor is handed its parts, not the node itself). */
    private Node current;

    private ModuleBinding(int index, int count, int id) {
        this.index = index;
        this.count = count;
        this.id = id;
    }

    /** {@code root} with {@code $index}, {@code $count} and {@code $id} bound; {@code root} itself when neither occurs. */
    static Node bind(Node root, int index, int count, int id) {
        return new ModuleBinding(index, count, id).of(root);
    }

    private Node of(Node n) {
        Node outer = current;
        current = n;
        try {
            return ExprTree.visit(n, this);
        } finally {
            current = outer;
        }
    }

    /** A leaf other than those variables stays as it is. */
    @Override
    protected Node leaf() {
        return current;
    }

    @Override
    public Node variable(String name) {
        switch (Vocabulary.LOGICAL_VARIABLES.indexOf(name)) {
            case Nodes.Var.INDEX: return new Nodes.Const(index);
            case Nodes.Var.COUNT: return new Nodes.Const(count);
            case Nodes.Var.ID: return new Nodes.Const(id);
            default: return current;
        }
    }

    @Override
    public Node unary(boolean not, Node arg) {
        Node n = current;
        Node a = of(arg);
        return a == arg ? n : ExprCompiler.fold(new Nodes.Unary(not, a));
    }

    @Override
    public Node binary(String op, Node left, Node right) {
        Node n = current;
        Node l = of(left);
        Node r = of(right);
        return l == left && r == right ? n
                : ExprCompiler.fold(Nodes.Binary.of(List.of(Nodes.Binary.SYMBOLS).indexOf(op), l, r));
    }

    @Override
    public Node logic(boolean and, Node left, Node right) {
        Node n = current;
        Node l = of(left);
        Node r = of(right);
        return l == left && r == right ? n : ExprCompiler.fold(and ? new Nodes.And(l, r) : new Nodes.Or(l, r));
    }

    @Override
    public Node conditional(Node cond, Node then, Node otherwise) {
        Node n = current;
        Node c = of(cond);
        Node a = of(then);
        Node b = of(otherwise);
        return c == cond && a == then && b == otherwise ? n : ExprCompiler.fold(new Nodes.If(c, a, b));
    }

    @Override
    public Node function1(String name, Node arg) {
        Node n = current;
        Node a = of(arg);
        return a == arg ? n : ExprCompiler.fold(Nodes.Func1.of(((Nodes.Func1) n).f, a));
    }

    @Override
    public Node function2(String name, Node a, Node b) {
        Node n = current;
        Node x = of(a);
        Node y = of(b);
        return x == a && y == b ? n : ExprCompiler.fold(new Nodes.Func2(((Nodes.Func2) n).f, x, y));
    }

    @Override
    public Node sum(List<Node> args) {
        Node n = current;
        Node[] bound = new Node[args.size()];
        boolean same = true;
        for (int i = 0; i < bound.length; i++) {
            bound[i] = of(args.get(i));
            same &= bound[i] == args.get(i);
        }
        return same ? n : ExprCompiler.fold(new Nodes.Sum(bound));
    }
}
