package org.parpe.gui.help;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The Markdown the tutorial pages use, as blocks and spans. */
class MarkdownTest {
    @Test
    void headingsParagraphsListsCodePicturesAndLinks() {
        Markdown.Page p = Markdown.parse("""
                # Lesson 3: **hello**
                <!-- edit: a hidden note -->
                Open [`03-hello.xml`](../../examples/03-hello.xml) and press
                **Run**.

                * first item
                  goes on
                2. second

                ![The IDE](img/03.png)

                ```xml
                <up angles="30"/>
                ```
                | a | b |
                |---|---|
                | 1 | 2 |
                """);
        List<Markdown.Block> b = p.blocks();
        assertEquals(Markdown.Kind.HEADING, b.get(0).kind());
        assertEquals("Lesson 3: hello", b.get(0).text());
        assertEquals(Markdown.Kind.PARAGRAPH, b.get(1).kind());
        assertEquals("Open 03-hello.xml and press Run.", b.get(1).text());
        assertEquals(List.of(new Markdown.Span(5, 12, Markdown.Style.CODE, null),
                new Markdown.Span(5, 12, Markdown.Style.LINK, "../../examples/03-hello.xml"),
                new Markdown.Span(28, 3, Markdown.Style.BOLD, null)), b.get(1).spans());
        assertEquals("\u2022 first item goes on", b.get(2).text());
        assertEquals("2. second", b.get(3).text());
        assertEquals(Markdown.Kind.IMAGE, b.get(4).kind());
        assertEquals("img/03.png", b.get(4).target());
        assertEquals("<up angles=\"30\"/>", b.get(5).text());
        assertEquals(Markdown.Kind.CODE, b.get(5).kind());
        assertEquals(Markdown.Kind.TABLE, b.get(6).kind());
        assertEquals("a\tb\n1\t2", b.get(6).text(), "a table keeps its rows and cells");
        assertEquals(1, b.get(6).level(), "one header row");
        assertEquals(7, b.size(), b.toString());
        assertEquals(List.of("../../examples/03-hello.xml"), p.links());
    }

    /** Issue 23, item 11: italics showed their asterisks, tables were flattened, links could not be followed. */
    @Test
    void italicsTablesAndLinksAsCommonMarkReadsThem() {
        Markdown.Page p = Markdown.parse("""
                Read it like this: *more bend helps* and see [lesson 4](04-travelling-waves.md).

                | run | bend | fell |
                |---|---|---|
                | 12 | 50 | 0 |
                """);
        Markdown.Block para = p.blocks().get(0);
        assertEquals("Read it like this: more bend helps and see lesson 4.", para.text());
        assertEquals(List.of(new Markdown.Span(19, 15, Markdown.Style.ITALIC, null),
                new Markdown.Span(43, 8, Markdown.Style.LINK, "04-travelling-waves.md")), para.spans());
        Markdown.Block table = p.blocks().get(1);
        assertEquals("run\tbend\tfell\n12\t50\t0", table.text());
        assertEquals(List.of(new Markdown.Span(0, 13, Markdown.Style.BOLD, null)), table.spans());
    }
}
