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
        assertEquals(List.of(new Markdown.Span(5, 12, true), new Markdown.Span(28, 3, false)), b.get(1).spans());
        assertEquals("\u2022 first item goes on", b.get(2).text());
        assertEquals("2. second", b.get(3).text());
        assertEquals(Markdown.Kind.IMAGE, b.get(4).kind());
        assertEquals("img/03.png", b.get(4).target());
        assertEquals("<up angles=\"30\"/>", b.get(5).text());
        assertEquals(Markdown.Kind.CODE, b.get(5).kind());
        assertEquals("a  b", b.get(6).text());
        assertEquals("1  2", b.get(7).text());
        assertEquals(8, b.size(), b.toString());
        assertEquals(List.of("../../examples/03-hello.xml"), p.links());
    }
}
