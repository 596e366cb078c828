package org.parpe.gui.help;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The part of Markdown the tutorial pages use, turned into blocks of styled text: headings,
 * paragraphs, bullet and numbered lists, fenced code, tables (kept as text), pictures, and
 * inline {@code **bold**}, {@code `code`} and links (their text is kept, their targets are
 * collected). HTML comments are dropped. No SWT here, so it is tested without a display.
 */
public final class Markdown {
    private static final Pattern IMAGE = Pattern.compile("^!\\[([^\\]]*)\\]\\(([^)\\s]+)\\)\\s*$");
    private static final Pattern INLINE = Pattern.compile("\\*\\*(.+?)\\*\\*|`([^`]+)`|\\[([^\\]]+)\\]\\(([^)\\s]+)\\)");

    /** The kinds of block. */
    public enum Kind { HEADING, PARAGRAPH, ITEM, CODE, IMAGE }

    /** A styled run inside a block's text: bold or code, from {@code start}, {@code length} chars. */
    public record Span(int start, int length, boolean code) {
    }

    /**
     * One block.
     *
     * @param kind  what it is
     * @param level heading level (1–6), list depth for items, else 0
     * @param text  the text without Markdown marks (for an image, its description)
     * @param spans bold and code runs in {@code text}
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
        List<Block> blocks = new ArrayList<>();
        List<String> links = new ArrayList<>();
        String[] lines = text.replace("\r\n", "\n").replaceAll("(?s)<!--.*?-->", "").split("\n", -1);
        StringBuilder para = new StringBuilder();
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i];
            String t = line.strip();
            if (t.startsWith("```")) {
                flush(para, blocks, links);
                StringBuilder code = new StringBuilder();
                for (i++; i < lines.length && !lines[i].strip().startsWith("```"); i++) {
                    code.append(code.length() == 0 ? "" : "\n").append(lines[i]);
                }
                blocks.add(new Block(Kind.CODE, 0, code.toString(), List.of(), null));
            } else if (t.isEmpty()) {
                flush(para, blocks, links);
            } else if (t.startsWith("#")) {
                flush(para, blocks, links);
                int level = (int) t.chars().takeWhile(c -> c == '#').count();
                blocks.add(inline(Kind.HEADING, Math.min(level, 6), t.substring(level).strip(), links));
            } else if (IMAGE.matcher(t).matches()) {
                flush(para, blocks, links);
                Matcher m = IMAGE.matcher(t);
                m.matches();
                blocks.add(new Block(Kind.IMAGE, 0, m.group(1), List.of(), m.group(2)));
            } else if (t.startsWith("|")) {
                flush(para, blocks, links);
                if (!t.matches("\\|[\\s|:-]+\\|?")) {
                    String cells = t.substring(1, t.endsWith("|") ? t.length() - 1 : t.length());
                    String row = String.join("  ", java.util.Arrays.stream(cells.split("\\|")).map(String::strip).toList());
                    blocks.add(inline(Kind.ITEM, 0, row, links));
                }
            } else if (t.matches("([*+-]|\\d+\\.)\\s+.*")) {
                flush(para, blocks, links);
                int depth = (line.length() - line.stripLeading().length()) / 2;
                String mark = t.substring(0, t.indexOf(' '));
                String body = t.substring(mark.length()).strip();
                String bullet = Character.isDigit(mark.charAt(0)) ? mark + " " : "\u2022 ";
                para.append(bullet).append(body);
                // continuation lines of the item follow until a blank line or the next item
                while (i + 1 < lines.length && !lines[i + 1].isBlank()
                        && !lines[i + 1].strip().matches("([*+-]|\\d+\\.)\\s+.*|#.*|```.*|\\|.*")) {
                    para.append(' ').append(lines[++i].strip());
                }
                blocks.add(inline(Kind.ITEM, depth + 1, para.toString(), links));
                para.setLength(0);
            } else {
                para.append(para.length() == 0 ? "" : " ").append(t);
            }
        }
        flush(para, blocks, links);
        return new Page(List.copyOf(blocks), List.copyOf(links));
    }

    private static void flush(StringBuilder para, List<Block> blocks, List<String> links) {
        if (para.length() > 0) {
            blocks.add(inline(Kind.PARAGRAPH, 0, para.toString(), links));
            para.setLength(0);
        }
    }

    private static Block inline(Kind kind, int level, String text, List<String> links) {
        StringBuilder out = new StringBuilder();
        List<Span> spans = new ArrayList<>();
        Matcher m = INLINE.matcher(text);
        int at = 0;
        while (m.find()) {
            out.append(text, at, m.start());
            if (m.group(1) != null) {
                spans.add(new Span(out.length(), m.group(1).length(), false));
                out.append(m.group(1));
            } else if (m.group(2) != null) {
                spans.add(new Span(out.length(), m.group(2).length(), true));
                out.append(m.group(2));
            } else {
                String label = m.group(3).replace("`", "");
                links.add(m.group(4));
                spans.add(new Span(out.length(), label.length(), m.group(3).startsWith("`")));
                out.append(label);
            }
            at = m.end();
        }
        out.append(text.substring(at));
        return new Block(kind, level, out.toString(), List.copyOf(spans), null);
    }
}
