package org.parpe.gui.help;

import java.util.ArrayList;
import java.util.List;
import org.commonmark.ext.gfm.tables.TableBlock;
import org.commonmark.ext.gfm.tables.TableCell;
import org.commonmark.ext.gfm.tables.TableHead;
import org.commonmark.ext.gfm.tables.TableRow;
import org.commonmark.ext.gfm.tables.TablesExtension;
import org.commonmark.node.BlockQuote;
import org.commonmark.node.BulletList;
import org.commonmark.node.Code;
import org.commonmark.node.Emphasis;
import org.commonmark.node.FencedCodeBlock;
import org.commonmark.node.HardLineBreak;
import org.commonmark.node.Heading;
import org.commonmark.node.Image;
import org.commonmark.node.IndentedCodeBlock;
import org.commonmark.node.Link;
import org.commonmark.node.ListItem;
import org.commonmark.node.Node;
import org.commonmark.node.OrderedList;
import org.commonmark.node.Paragraph;
import org.commonmark.node.SoftLineBreak;
import org.commonmark.node.StrongEmphasis;
import org.commonmark.node.Text;
import org.commonmark.parser.Parser;

/**
 * A tutorial page's Markdown turned into blocks of styled text by commonmark-java (CommonMark
 * with GitHub tables): headings, paragraphs, bullet and numbered lists, quotes, fenced code,
 * tables (one line per row, cells separated by tabs), pictures, and inline bold, italics, code
 * and links (their targets are kept, to be clicked). HTML (comments) is dropped. No SWT here, so
 * it is tested without a display. {@link #parse} takes the page's text, so a caller may change
 * the text first (the installed launcher's name).
 */
public final class Markdown {
    private static final Parser PARSER = Parser.builder().extensions(List.of(TablesExtension.create())).build();

    /** The kinds of block. */
    public enum Kind { HEADING, PARAGRAPH, ITEM, CODE, IMAGE, TABLE }

    /** How a run of text is styled. */
    public enum Style { BOLD, ITALIC, CODE, LINK }

    /**
     * A styled run inside a block's text.
     *
     * @param start  its first character in the block's text
     * @param length its length
     * @param style  bold, italic, code or a link
     * @param target a link's target as written (null for the others)
     */
    public record Span(int start, int length, Style style, String target) {
        /** Whether the run is code (shown in the code font). */
        public boolean code() {
            return style == Style.CODE;
        }
    }

    /**
     * One block.
     *
     * @param kind   what it is
     * @param level  heading level (1–6), list depth for items, the header rows of a table, else 0
     * @param text   the text without Markdown marks (for an image, its description; for a table,
     *               one line per row with the cells separated by tabs)
     * @param spans  the styled runs in {@code text}
     * @param target for an image, its path as written
     */
    public record Block(Kind kind, int level, String text, List<Span> spans, String target) {
    }

    /** A page: its blocks and every link target in order (scripts, other pages). */
    public record Page(List<Block> blocks, List<String> links) {
    }

    private Markdown() {
    }

    /** Parses {@code text}. */
    public static Page parse(String text) {
        Builder b = new Builder();
        b.blocks(PARSER.parse(text), 0);
        return new Page(List.copyOf(b.blocks), List.copyOf(b.links));
    }

    /** Walks commonmark's tree into blocks. */
    private static final class Builder {
        private final List<Block> blocks = new ArrayList<>();
        private final List<String> links = new ArrayList<>();

        void blocks(Node parent, int depth) {
            for (Node n = parent.getFirstChild(); n != null; n = n.getNext()) {
                block(n, depth);
            }
        }

        private void block(Node n, int depth) {
            if (n instanceof Heading h) {
                blocks.add(inline(Kind.HEADING, h.getLevel(), "", h));
            } else if (n instanceof Paragraph p) {
                Image only = p.getFirstChild() instanceof Image img && img.getNext() == null ? img : null;
                if (only != null) {
                    blocks.add(new Block(Kind.IMAGE, 0, plain(only), List.of(), only.getDestination()));
                } else {
                    blocks.add(inline(depth > 0 ? Kind.ITEM : Kind.PARAGRAPH, depth, "", p));
                }
            } else if (n instanceof FencedCodeBlock c) {
                blocks.add(new Block(Kind.CODE, 0, c.getLiteral().stripTrailing(), List.of(), null));
            } else if (n instanceof IndentedCodeBlock c) {
                blocks.add(new Block(Kind.CODE, 0, c.getLiteral().stripTrailing(), List.of(), null));
            } else if (n instanceof BulletList || n instanceof OrderedList) {
                int number = n instanceof OrderedList ol ? ol.getStartNumber() : 0;
                for (Node item = n.getFirstChild(); item != null; item = item.getNext()) {
                    listItem((ListItem) item, depth + 1, number == 0 ? "\u2022 " : number++ + ". ");
                }
            } else if (n instanceof BlockQuote) {
                blocks(n, depth);
            } else if (n instanceof TableBlock t) {
                table(t);
            }
            // HTML blocks (comments) and thematic breaks are left out.
        }

        private void listItem(ListItem item, int depth, String mark) {
            boolean first = true;
            for (Node n = item.getFirstChild(); n != null; n = n.getNext()) {
                if (first && n instanceof Paragraph p) {
                    blocks.add(inline(Kind.ITEM, depth, mark, p));
                } else {
                    block(n, depth);
                }
                first = false;
            }
        }

        private void table(TableBlock t) {
            StringBuilder out = new StringBuilder();
            List<Span> spans = new ArrayList<>();
            int head = 0;
            for (Node section = t.getFirstChild(); section != null; section = section.getNext()) {
                for (Node row = section.getFirstChild(); row != null; row = row.getNext()) {
                    if (!(row instanceof TableRow)) {
                        continue;
                    }
                    if (out.length() > 0) {
                        out.append('\n');
                    }
                    int rowStart = out.length();
                    for (Node cell = row.getFirstChild(); cell != null; cell = cell.getNext()) {
                        if (cell != row.getFirstChild()) {
                            out.append('\t');
                        }
                        inlines((TableCell) cell, out, spans);
                    }
                    if (section instanceof TableHead) {
                        head++;
                        spans.add(new Span(rowStart, out.length() - rowStart, Style.BOLD, null));
                    }
                }
            }
            blocks.add(new Block(Kind.TABLE, head, out.toString(), List.copyOf(spans), null));
        }

        private Block inline(Kind kind, int level, String prefix, Node parent) {
            StringBuilder out = new StringBuilder(prefix);
            List<Span> spans = new ArrayList<>();
            inlines(parent, out, spans);
            return new Block(kind, level, out.toString(), List.copyOf(spans), null);
        }

        private void inlines(Node parent, StringBuilder out, List<Span> spans) {
            for (Node n = parent.getFirstChild(); n != null; n = n.getNext()) {
                int start = out.length();
                if (n instanceof Text t) {
                    out.append(t.getLiteral());
                } else if (n instanceof Code c) {
                    out.append(c.getLiteral());
                    spans.add(new Span(start, c.getLiteral().length(), Style.CODE, null));
                } else if (n instanceof SoftLineBreak) {
                    out.append(' ');
                } else if (n instanceof HardLineBreak) {
                    out.append('\n');
                } else if (n instanceof StrongEmphasis || n instanceof Emphasis) {
                    inlines(n, out, spans);
                    spans.add(new Span(start, out.length() - start, n instanceof StrongEmphasis ? Style.BOLD : Style.ITALIC, null));
                } else if (n instanceof Link l) {
                    inlines(n, out, spans);
                    links.add(l.getDestination());
                    spans.add(new Span(start, out.length() - start, Style.LINK, l.getDestination()));
                } else if (n instanceof Image i) {
                    out.append(plain(i));
                } else {
                    inlines(n, out, spans); // inline HTML and the like: their text only
                }
            }
        }

        private static String plain(Node n) {
            StringBuilder b = new StringBuilder();
            for (Node c = n.getFirstChild(); c != null; c = c.getNext()) {
                if (c instanceof Text t) {
                    b.append(t.getLiteral());
                } else if (c instanceof Code code) {
                    b.append(code.getLiteral());
                } else {
                    b.append(plain(c));
                }
            }
            return b.toString();
        }
    }
}
