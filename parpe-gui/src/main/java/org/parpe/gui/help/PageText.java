package org.parpe.gui.help;

import org.parpe.gui.text.UiMsg;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.StyleRange;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.Font;
import org.eclipse.swt.graphics.GlyphMetrics;
import org.eclipse.swt.graphics.Image;

/**
 * A lesson's Markdown laid out in the tutorial's {@link StyledText}: its text, the style ranges
 * of headings, code, emphasis and links, the pictures as embedded objects, tables as tab stops
 * (or as cards where they are wider than the column), and the runs a click follows.
 */
final class PageText {
    private static final char OBJECT = '\uFFFC';

    /** A clickable run: a link's target, or code to put into the editor. */
    record Link(int start, int length, String link, String code) {
        boolean holds(int offset) {
            return offset >= start && offset < start + length;
        }
    }

    private final StyledText text;
    private final Font heading;
    private final Font code;
    private final boolean offerInsert;
    /** The picture of a file, scaled to the column, or null where it cannot be shown. */
    private final Function<Path, Image> pictures;
    private final Color codeBack;
    private final Color link;
    private final StringBuilder all = new StringBuilder();
    private final List<StyleRange> styles = new ArrayList<>();
    private final List<int[]> tables = new ArrayList<>();
    private final List<int[]> cards = new ArrayList<>();
    private final List<Link> links = new ArrayList<>();

    /** For one page: {@code offerInsert} puts "insert into the editor" under each XML code block. */
    PageText(StyledText text, Font heading, Font code, boolean offerInsert, Function<Path, Image> pictures) {
        this.text = text;
        this.heading = heading;
        this.code = code;
        this.offerInsert = offerInsert;
        this.pictures = pictures;
        codeBack = text.getDisplay().getSystemColor(SWT.COLOR_WIDGET_LIGHT_SHADOW);
        link = text.getDisplay().getSystemColor(SWT.COLOR_LINK_FOREGROUND);
    }

    /** Shows {@code page}, whose links start from {@code dir}; returns its clickable runs. */
    List<Link> show(Markdown.Page page, Path dir) {
        for (Markdown.Block given : page.blocks()) {
            // a table wider than the column (a docked tutorial) reads as cards, not as cells wrapping into each other
            Markdown.Block b = given.kind() == Markdown.Kind.TABLE && Tables.tooWide(text, given.text()) ? TableCards.cards(given) : given;
            switch (b.kind()) {
                case IMAGE -> picture(b, dir.resolve(b.target()).normalize());
                case CODE -> code(b);
                default -> prose(b, b != given);
            }
            all.append("\n\n");
        }
        text.setText(all.toString());
        styles.sort(java.util.Comparator.comparingInt(r -> r.start));
        text.setStyleRanges(merge(styles));
        for (int[] t : tables) {
            Tables.tabStops(text, t[0], t[1]);
        }
        for (int[] c : cards) {
            Tables.hangCards(text, c[0], c[1]);
        }
        return List.copyOf(links);
    }

    private void picture(Markdown.Block b, Path file) {
        int start = all.length();
        Image img = pictures.apply(file);
        if (img == null) {
            all.append(UiMsg.TUTORIAL_PICTURE.text(b.text()));
            return;
        }
        all.append(OBJECT);
        // scaled to the column, a screenshot is past reading: a click shows it at full size
        links.add(new Link(start, 1, file.toString(), null));
        String full = "\n" + UiMsg.TUTORIAL_FULL_SIZE.text();
        links.add(new Link(start + 2, full.length() - 1, file.toString(), null));
        styles.add(linkStyle(start + 2, full.length() - 1, link));
        all.append(full);
        StyleRange r = new StyleRange();
        r.start = start;
        r.length = 1;
        r.data = img;
        org.eclipse.swt.graphics.Rectangle bounds = img.getBounds();
        r.metrics = new GlyphMetrics(bounds.height, 0, bounds.width);
        styles.add(r);
    }

    private void code(Markdown.Block b) {
        int start = all.length();
        all.append(b.text());
        StyleRange r = new StyleRange(start, b.text().length(), null, codeBack);
        r.font = code;
        styles.add(r);
        if (offerInsert && b.text().strip().startsWith("<")) {
            // A lesson's XML goes to the editor with one click (where it belongs, one undo).
            String action = "\n" + UiMsg.TUTORIAL_INSERT_CODE.text();
            int at = all.length() + 1;
            all.append(action);
            links.add(new Link(at, action.length() - 1, null, b.text()));
            styles.add(linkStyle(at, action.length() - 1, link));
        }
    }

    /** A heading, paragraph, list item or table; {@code asCards}: a table turned into cards. */
    private void prose(Markdown.Block b, boolean asCards) {
        int start = all.length();
        String indent = b.kind() == Markdown.Kind.ITEM ? "    ".repeat(Math.max(0, b.level() - 1)) + "  " : "";
        all.append(indent).append(b.text());
        int base = start + indent.length();
        if (b.kind() == Markdown.Kind.HEADING) {
            StyleRange r = new StyleRange(start, b.text().length(), null, null);
            r.font = heading;
            styles.add(r);
        }
        if (b.kind() == Markdown.Kind.TABLE) {
            tables.add(new int[] {start, b.text().split("\n", -1).length});
        } else if (asCards) {
            cards.add(new int[] {start, b.text().split("\n", -1).length});
        }
        for (Markdown.Span s : b.spans()) {
            styles.add(span(base + s.start(), s));
            if (s.style() == Markdown.Style.LINK) {
                links.add(new Link(base + s.start(), s.length(), s.target(), null));
            }
        }
    }

    private StyleRange span(int at, Markdown.Span s) {
        StyleRange r = new StyleRange(at, s.length(), null, null);
        switch (s.style()) {
            case CODE -> r.font = code;
            case BOLD -> r.fontStyle = SWT.BOLD;
            case ITALIC -> r.fontStyle = SWT.ITALIC;
            case LINK -> {
                return linkStyle(at, s.length(), link);
            }
        }
        return r;
    }

    private static StyleRange linkStyle(int at, int length, Color link) {
        StyleRange r = new StyleRange(at, length, link, null);
        r.underline = true;
        r.underlineStyle = SWT.UNDERLINE_LINK;
        return r;
    }

    /**
     * Style ranges that never overlap (StyledText refuses overlapping ones): where a run lies
     * inside another (bold inside a link), the inner one is kept with the outer one's font.
     */
    private static StyleRange[] merge(List<StyleRange> sorted) {
        List<StyleRange> out = new ArrayList<>();
        int end = 0;
        for (StyleRange r : sorted) {
            if (r.start >= end) {
                out.add(r);
                end = r.start + r.length;
            } else if (r.underline && !out.isEmpty()) {
                // A link around code: the code keeps its font and looks like a link too.
                StyleRange kept = out.get(out.size() - 1);
                kept.underline = true;
                kept.underlineStyle = r.underlineStyle;
                kept.foreground = r.foreground;
            }
        }
        return out.toArray(new StyleRange[0]);
    }
}
