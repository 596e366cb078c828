package org.parpe.gui.editor;

import org.parpe.gui.text.UiMsg;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import org.eclipse.jface.resource.JFaceResources;
import org.eclipse.jface.text.BadLocationException;
import org.eclipse.jface.text.CursorLinePainter;
import org.eclipse.jface.text.Document;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.IDocumentPartitioner;
import org.eclipse.jface.text.Position;
import org.eclipse.jface.text.rules.FastPartitioner;
import org.eclipse.jface.text.source.Annotation;
import org.eclipse.jface.text.source.AnnotationModel;
import org.eclipse.jface.text.source.AnnotationPainter;
import org.eclipse.jface.text.source.AnnotationRulerColumn;
import org.eclipse.jface.text.source.CompositeRuler;
import org.eclipse.jface.text.source.IAnnotationAccess;
import org.eclipse.jface.text.source.IAnnotationAccessExtension;
import org.eclipse.jface.text.source.IAnnotationHover;
import org.eclipse.jface.text.source.ISourceViewer;
import org.eclipse.jface.text.source.LineNumberRulerColumn;
import org.eclipse.jface.text.source.SourceViewer;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Canvas;
import org.eclipse.swt.widgets.Composite;
import org.parpe.core.edit.Replacement;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.SourcePos;

/**
 * The PARSL source editor: a JFace {@link SourceViewer} with XML colouring, line numbers,
 * error markers (ruler badges, squiggles, hovers), the current line highlighted, undo/redo and
 * content assist (Ctrl+Space, or automatically after {@code <}, {@code $} and {@code "}).
 * A text over {@link #COLOUR_LIMIT} characters is shown plain: colouring it would partition and
 * style the whole text at once, seconds of the UI thread and hundreds of megabytes; and at most
 * {@link #MARKER_LIMIT} problems are marked.
 */
public final class ParslEditor {
    private static final String SQUIGGLE = "org.parpe.gui.squiggle";
    private static final Color LINE_BG = org.parpe.gui.panels.Theme.pick(0xF2F6FC, 0x383D47);
    private static final Color RULER_FG = org.parpe.gui.panels.Theme.pick(0x9098A8, 0x8890A0);
    /** Texts longer than this (characters) are not coloured. */
    public static final int COLOUR_LIMIT = 1_000_000;
    /** At most this many problems are marked in the text and the ruler (Problems lists them all). */
    public static final int MARKER_LIMIT = 2_000;

    private final SourceViewer viewer;
    private final Document document = new Document();
    private final AnnotationModel annotations = new AnnotationModel();
    private final IDocumentPartitioner partitioner = new FastPartitioner(XmlScanners.partitionScanner(), XmlScanners.TYPES);
    private boolean plain;
    private volatile NameIndex backgroundNames = NameIndex.of("");

    /** Creates the editor in {@code parent}. */
    public ParslEditor(Composite parent) {
        IAnnotationAccess access = new Access();
        CompositeRuler ruler = new CompositeRuler();
        AnnotationRulerColumn marks = new AnnotationRulerColumn(annotations, 16, access);
        marks.addAnnotationType(ProblemAnnotation.ERROR);
        marks.addAnnotationType(ProblemAnnotation.WARNING);
        LineNumberRulerColumn lines = new LineNumberRulerColumn();
        lines.setForeground(RULER_FG);
        ruler.addDecorator(0, marks);
        ruler.addDecorator(1, lines);
        viewer = new SourceViewer(parent, ruler, null, false, SWT.V_SCROLL | SWT.H_SCROLL | SWT.MULTI | SWT.BORDER);
        viewer.configure(new ParslViewerConfiguration(hover(), () -> plain, this::names));
        partitioner.connect(document);
        document.setDocumentPartitioner(partitioner);
        viewer.setDocument(document, annotations);
        viewer.getTextWidget().setFont(JFaceResources.getTextFont());

        AnnotationPainter painter = new AnnotationPainter(viewer, access);
        painter.addTextStyleStrategy(SQUIGGLE, new AnnotationPainter.UnderlineStrategy(SWT.UNDERLINE_SQUIGGLE));
        painter.addAnnotationType(ProblemAnnotation.ERROR, SQUIGGLE);
        painter.addAnnotationType(ProblemAnnotation.WARNING, SQUIGGLE);
        painter.setAnnotationTypeColor(ProblemAnnotation.ERROR, ProblemAnnotation.ERROR_COLOR);
        painter.setAnnotationTypeColor(ProblemAnnotation.WARNING, ProblemAnnotation.WARNING_COLOR);
        viewer.addPainter(painter);
        viewer.addTextPresentationListener(painter);
        CursorLinePainter cursorLine = new CursorLinePainter(viewer);
        cursorLine.setHighlightColor(LINE_BG);
        viewer.addPainter(cursorLine);

        viewer.appendVerifyKeyListener(e -> {
            if ((e.stateMask & SWT.MOD1) != 0 && e.character == ' ') {
                viewer.doOperation(ISourceViewer.CONTENTASSIST_PROPOSALS);
                e.doit = false;
            }
        });
    }

    /** The viewer, for operations (undo, find, ...). */
    public SourceViewer viewer() {
        return viewer;
    }

    /**
     * Applies {@code edit} to the document as one replacement spanning all of its ranges (one
     * Edit > Undo takes it back); returns the offset of its first range.
     *
     * @throws BadLocationException when the text has changed since the edit was made
     */
    public int apply(TextEdit edit) throws BadLocationException {
        List<Replacement> rs = edit.replacements();
        if (rs.isEmpty()) {
            return -1;
        }
        String text = document.get();
        int from = rs.get(0).offset();
        int to = rs.get(rs.size() - 1).end();
        if (to > text.length()) {
            throw new BadLocationException("the edit ends at " + to + ", the text at " + text.length());
        }
        String after = edit.apply(text);
        document.replace(from, to - from, after.substring(from, after.length() - (text.length() - to)));
        return from;
    }

    /** The text widget. */
    /** The syntax colours, the current line's background and the line numbers' colour (tests check their contrast). */
    public static java.util.List<Color> colours() {
        return java.util.List.of(XmlScanners.ELEMENT, XmlScanners.ATTRIBUTE, XmlScanners.VALUE, XmlScanners.COMMENT_COLOR,
                XmlScanners.PUNCT, XmlScanners.NUMBER);
    }

    /** The background of the line with the caret. */
    public static Color currentLine() {
        return LINE_BG;
    }

    public StyledText widget() {
        return viewer.getTextWidget();
    }

    /** The document being edited. */
    public IDocument document() {
        return document;
    }

    /**
     * Replaces the whole text and forgets the undo history (a newly opened file). Colouring is
     * switched off for a text over {@link #COLOUR_LIMIT} characters, on again for a smaller one.
     */
    public void setText(String text) {
        boolean big = text.length() > COLOUR_LIMIT;
        if (big && !plain) {
            // Disconnect first, so that the partitioner never scans the large text.
            plain = true;
            partitioner.disconnect();
            document.setDocumentPartitioner(null);
        }
        annotations.removeAllAnnotations();
        backgroundNames = NameIndex.of("");
        document.set(text);
        if (!big && plain) {
            plain = false;
            partitioner.connect(document);
            document.setDocumentPartitioner(partitioner);
            viewer.invalidateTextPresentation();
        }
        viewer.getUndoManager().reset();
        viewer.setSelectedRange(0, 0);
    }

    /**
     * The names {@code text} defines, for completion: scanned now and joined with the names of
     * the last program the {@link ScriptDocument} loaded (which knows the included files' names), or
     * for a text over {@link #COLOUR_LIMIT} (a scan takes about a second at 10 MB) only the
     * latter.
     */
    public NameIndex names(String text) {
        return text.length() > COLOUR_LIMIT ? backgroundNames : NameIndex.of(text).with(backgroundNames);
    }

    /**
     * Keeps the names found off the UI thread by the {@link ScriptDocument}: those of the program
     * it loaded, or for a large text that did not load, those of a scan.
     */
    public void setNames(NameIndex names) {
        backgroundNames = names;
    }

    /** Whether the text is shown without colouring (it was too large when opened). */
    public boolean plain() {
        return plain;
    }

    /** Runs one {@link org.eclipse.jface.text.ITextOperationTarget} operation if it is possible. */
    public void run(int operation) {
        if (viewer.canDoOperation(operation)) {
            viewer.doOperation(operation);
        }
    }

    /** Shows {@code diagnostics} (those of this document) as markers. */
    public void setDiagnostics(List<Diagnostic> diagnostics) {
        annotations.removeAllAnnotations();
        String text = document.get();
        for (Diagnostic d : diagnostics.subList(0, Math.min(diagnostics.size(), MARKER_LIMIT))) {
            int[] span = span(d.pos(), text);
            if (span != null) {
                annotations.addAnnotation(new ProblemAnnotation(d), new Position(span[0], span[1]));
            }
        }
        widget().redraw();
    }

    /** The markers now shown. */
    public List<ProblemAnnotation> markers() {
        List<ProblemAnnotation> out = new ArrayList<>();
        for (Iterator<Annotation> it = annotations.getAnnotationIterator(); it.hasNext();) {
            if (it.next() instanceof ProblemAnnotation p) {
                out.add(p);
            }
        }
        return out;
    }

    /** The line (1-based) of a marker. */
    public int lineOf(ProblemAnnotation a) {
        Position p = annotations.getPosition(a);
        try {
            return p == null ? -1 : document.getLineOfOffset(p.getOffset()) + 1;
        } catch (BadLocationException e) {
            return -1;
        }
    }

    /** Selects the word at 1-based {@code line}, {@code column}, scrolls to it and focuses the editor. */
    public void reveal(int line, int column) {
        reveal(span(line, column));
    }

    /** Selects the word at {@code pos} (a place in this document), scrolls to it and focuses the editor. */
    public void reveal(SourcePos pos) {
        reveal(span(pos, document.get()));
    }

    private void reveal(int[] span) {
        if (span == null) {
            return;
        }
        viewer.setSelectedRange(span[0], span[1]);
        viewer.revealRange(span[0], span[1]);
        widget().setFocus();
    }

    /**
     * The offset and length of the name at {@code pos} in {@code text} (the document's, got once
     * for all markers): at the offset the loader recorded (a place at a line's end names the
     * line's last character, as {@link #span(int, int)} does), else at its line and column.
     */
    private int[] span(SourcePos pos, String text) {
        int off = pos.offset();
        if (off < 0 || off > text.length()) {
            return span(pos.line(), pos.column());
        }
        int lineStart = text.lastIndexOf('\n', off - 1) + 1;
        while (off > lineStart && (off == text.length() || text.charAt(off) == '\n' || text.charAt(off) == '\r')) {
            off--;
        }
        int end = off;
        while (end < text.length() && (XmlScanners.isNameChar(text.charAt(end)) || end == off && text.charAt(end) == '<')) {
            end++;
        }
        return new int[] {off, Math.max(1, end - off)};
    }

    /** The offset and length of the name at a 1-based place (at least one character), or null. */
    private int[] span(int line, int column) {
        try {
            int l = Math.max(0, Math.min(line - 1, document.getNumberOfLines() - 1));
            int start = document.getLineOffset(l);
            int len = document.getLineLength(l) - lineDelimiterLength(l);
            int off = start + Math.max(0, Math.min(column - 1, Math.max(0, len - 1)));
            // Only this line: copying the whole text per marker made many markers quadratic.
            String text = document.get(start, len);
            int end = off;
            while (end < start + len && (XmlScanners.isNameChar(text.charAt(end - start))
                    || end == off && text.charAt(end - start) == '<')) {
                end++;
            }
            return new int[] {off, Math.max(1, Math.min(end - off, start + len - off))};
        } catch (BadLocationException e) {
            return null;
        }
    }

    private int lineDelimiterLength(int line) throws BadLocationException {
        String d = document.getLineDelimiter(line);
        return d == null ? 0 : d.length();
    }

    private IAnnotationHover hover() {
        return (sourceViewer, lineNumber) -> {
            StringBuilder sb = new StringBuilder();
            for (ProblemAnnotation a : markers()) {
                if (lineOf(a) == lineNumber + 1) {
                    sb.append(sb.length() > 0 ? "\n" : "").append(a.diagnostic().severity().word())
                            .append(": ").append(a.getText());
                }
            }
            return sb.length() == 0 ? null : sb.toString();
        };
    }

    private static final class Access implements IAnnotationAccess, IAnnotationAccessExtension {
        @Override
        public String getTypeLabel(Annotation annotation) {
            return (annotation instanceof ProblemAnnotation p && p.isError() ? UiMsg.ANNOTATION_ERROR : UiMsg.ANNOTATION_WARNING).text();
        }

        @Override
        public int getLayer(Annotation annotation) {
            return annotation instanceof ProblemAnnotation p ? p.getLayer() : DEFAULT_LAYER;
        }

        @Override
        public void paint(Annotation annotation, GC gc, Canvas canvas, Rectangle bounds) {
            if (annotation instanceof ProblemAnnotation p) {
                p.paint(gc, canvas, bounds);
            }
        }

        @Override
        public boolean isPaintable(Annotation annotation) {
            return annotation instanceof ProblemAnnotation;
        }

        @Override
        public boolean isSubtype(Object annotationType, Object potentialSupertype) {
            return annotationType.equals(potentialSupertype);
        }

        @Override
        public Object[] getSupertypes(Object annotationType) {
            return new Object[0];
        }

        /** Required by the interface, deprecated there; only its type matters here. */
        @Deprecated
        @Override
        public Object getType(Annotation annotation) {
            return annotation.getType();
        }

        /** Required by the interface, deprecated there; only its type matters here. */
        @Deprecated
        @Override
        public boolean isMultiLine(Annotation annotation) {
            return false;
        }

        /** Required by the interface, deprecated there; only its type matters here. */
        @Deprecated
        @Override
        public boolean isTemporary(Annotation annotation) {
            return true;
        }
    }
}
