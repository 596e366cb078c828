package org.parpe.gui.help;

import org.parpe.gui.text.UiMsg;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.stream.Stream;
import org.eclipse.jface.resource.JFaceResources;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.swt.graphics.Font;
import org.eclipse.swt.graphics.FontData;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Shell;
import org.parpe.core.text.Lang;

/**
 * Help → Tutorial: the lessons of {@code docs/tutorial} in a list and the chosen lesson rendered
 * from its Markdown with its pictures, in the IDE's language where they are translated
 * ({@link Lessons}). "Open the lesson's script" puts the lesson's example in the
 * editor (through the IDE's usual unsaved-text check). Either docked in the IDE ({@link #docked}:
 * a tab of its own, the list above the lesson) where the screen has no room beside the IDE (a
 * 1366×768 laptop), or a normal window, not one pinned above the IDE, sized to fit on the screen
 * beside it; it closes with the IDE.
 */
public final class TutorialWindow {
    private static final int IMAGE_WIDTH = 720;

    private final Shell shell;
    /** What holds the tutorial: its own window, or a composite in the IDE's dock. */
    private final Composite root;
    private final boolean docked;
    private final Path folder;
    private final List<Path> pages;
    private final org.eclipse.swt.widgets.List index;
    private final StyledText text;
    private final Button open;
    private final Font normal;
    private Font heading;
    private Font code;
    private int zoom;
    private final List<Image> images = new ArrayList<>();
    /** The files of the page's pictures, which a click shows at full size. */
    private final java.util.Set<String> pictures = new java.util.HashSet<>();
    private final Consumer<Path> openScript;
    private final Consumer<String> insertCode;
    private final List<PageText.Link> links = new ArrayList<>();
    private Path script;
    /** The text's width when the page shown was laid out. */
    private int renderedWidth = -1;
    private boolean installed;

    /**
     * A tutorial window over {@code folder} (holding {@code index.md}, the numbered lessons and
     * {@code teachers.md}); {@code openScript} opens a lesson's script in the editor.
     */
    public TutorialWindow(Shell parent, Path folder, Consumer<Path> openScript) {
        this(parent, folder, openScript, null);
    }

    /**
     * As {@link #TutorialWindow(Shell, Path, Consumer)}; {@code insertCode} (may be null) puts a
     * lesson's XML into the editor, offered under each XML code block.
     */
    public TutorialWindow(Shell parent, Path folder, Consumer<Path> openScript, Consumer<String> insertCode) {
        this(parent, null, folder, openScript, insertCode);
    }

    /**
     * The tutorial docked in {@code dock} (a tab of the IDE), not in a window of its own: the list
     * of lessons above the lesson, so that a narrow column holds both.
     */
    public static TutorialWindow docked(Composite dock, Path folder, Consumer<Path> openScript, Consumer<String> insertCode) {
        return new TutorialWindow(dock.getShell(), dock, folder, openScript, insertCode);
    }

    private TutorialWindow(Shell parent, Composite dock, Path folder, Consumer<Path> openScript, Consumer<String> insertCode) {
        this.folder = folder;
        this.openScript = openScript;
        this.insertCode = insertCode;
        this.pages = Lessons.pages(folder, Lang.current());
        docked = dock != null;
        if (docked) {
            shell = parent;
            root = new Composite(dock, SWT.NONE);
        } else {
            // A top-level window (no parent): one transient for the IDE stays above it and hides the editor.
            shell = new Shell(parent.getDisplay(), SWT.SHELL_TRIM);
            parent.addListener(SWT.Dispose, e -> {
                if (!shell.isDisposed()) {
                    shell.dispose();
                }
            });
            shell.setText(UiMsg.TUTORIAL_WINDOW_TITLE.text());
            root = shell;
        }
        root.setLayout(new GridLayout(1, false));
        SashForm sash = new SashForm(root, docked ? SWT.VERTICAL : SWT.HORIZONTAL);
        sash.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        index = new org.eclipse.swt.widgets.List(sash, SWT.BORDER | SWT.SINGLE | SWT.V_SCROLL);
        text = new StyledText(sash, SWT.BORDER | SWT.WRAP | SWT.V_SCROLL | SWT.READ_ONLY);
        text.setMargins(16, 12, 16, 12);
        sash.setWeights(docked ? new int[] {18, 82} : new int[] {22, 78});
        normal = text.getFont();
        fonts();
        // the pictures and the tables are laid out for the column's width: again when it changes (the dock's sash)
        text.addListener(SWT.Resize, e -> text.getDisplay().timerExec(200, this::fitWidth));
        zoomKeys();
        clicks();
        open = buttons();
        for (Path p : pages) {
            index.add(title(p));
        }
        index.addListener(SWT.Selection, e -> show(index.getSelectionIndex()));
        root.addListener(SWT.Dispose, e -> {
            disposeImages();
            disposeFonts();
        });
        if (!docked) {
            fitTo(parent.getMonitor().getClientArea());
        }
    }

    /** Ctrl + / Ctrl − / Ctrl 0 as in the IDE's editor (a projector): anywhere in this window. */
    private void zoomKeys() {
        org.eclipse.swt.widgets.Listener keys = e -> {
            var focus = e.display.getFocusControl();
            if ((e.stateMask & SWT.MOD1) != 0 && inside(focus)
                    && org.parpe.gui.panels.Zoom.step(e) != org.parpe.gui.panels.Zoom.NONE) {
                zoom(org.parpe.gui.panels.Zoom.step(e));
                e.doit = false;
                e.type = SWT.None;
            }
        };
        shell.getDisplay().addFilter(SWT.KeyDown, keys);
        root.addListener(SWT.Dispose, e -> e.display.removeFilter(SWT.KeyDown, keys));
    }

    /** Links and pictures followed on a click, the hand over them; pictures drawn in the text. */
    private void clicks() {
        text.addListener(SWT.MouseUp, e -> {
            if (e.button == 1 && text.getSelectionCount() == 0) {
                int at = text.getOffsetAtPoint(new org.eclipse.swt.graphics.Point(e.x, e.y));
                if (at >= 0) {
                    click(at);
                }
            }
        });
        text.addListener(SWT.MouseMove, e -> {
            int at = text.getOffsetAtPoint(new org.eclipse.swt.graphics.Point(e.x, e.y));
            boolean over = at >= 0 && links.stream().anyMatch(t -> t.holds(at));
            text.setCursor(over ? text.getDisplay().getSystemCursor(SWT.CURSOR_HAND) : null);
        });
        text.addPaintObjectListener(e -> {
            Object data = e.style.data;
            if (data instanceof Image img && !img.isDisposed()) {
                e.gc.drawImage(img, e.x, e.y + e.ascent - e.style.metrics.ascent);
            }
        });
    }

    /** Previous, Next and "Open the lesson's script"; returns the last. */
    private Button buttons() {
        Composite buttons = org.parpe.gui.panels.WrapRow.of(root); // "Open NAME" wraps under the others in a narrow dock
        button(buttons, UiMsg.TUTORIAL_PREVIOUS.text(), () -> show(index.getSelectionIndex() - 1));
        button(buttons, UiMsg.TUTORIAL_NEXT.text(), () -> show(index.getSelectionIndex() + 1));
        return button(buttons, UiMsg.TUTORIAL_OPEN_SCRIPT.text(), () -> {
            if (script != null) {
                openScript.accept(script);
            }
        });
    }

    /** Lays the page out again if the text's width changed since it was laid out, staying where it was scrolled to. */
    private void fitWidth() {
        if (text.isDisposed() || index.getSelectionIndex() < 0 || text.getClientArea().width == renderedWidth) {
            return;
        }
        int top = text.getTopPixel();
        show(index.getSelectionIndex());
        text.setTopPixel(top);
    }

    /** Whether {@code c} is part of the tutorial. */
    private boolean inside(org.eclipse.swt.widgets.Control c) {
        for (; c != null; c = c.getParent()) {
            if (c == root) {
                return true;
            }
        }
        return false;
    }

    /**
     * At most 1100×800 and never past the screen's working area; on the right of it, so that the
     * IDE's editor on the left stays in sight.
     */
    private void fitTo(org.eclipse.swt.graphics.Rectangle area) {
        int w = Math.min(1100, Math.max(480, area.width * 45 / 100));
        int h = Math.min(800, area.height);
        shell.setBounds(area.x + area.width - w, area.y, w, h);
    }

    private static Button button(Composite parent, String label, Runnable action) {
        Button b = new Button(parent, SWT.PUSH);
        b.setText(label);
        b.addListener(SWT.Selection, e -> action.run());
        return b;
    }

    /** Shows commands as the installed PARPE runs them ({@code parpe …}, see {@link CommandNames}); call before {@link #open}. */
    public void showInstalledCommands(boolean installed) {
        this.installed = installed;
    }

    /** Opens the window (docked: shows the tutorial) on the first page. */
    public void open() {
        if (!docked) {
            shell.open();
        }
        show(0);
    }

    /** The tutorial's own window, or the IDE's when docked. */
    public Shell shell() {
        return shell;
    }

    /** What holds the tutorial: its window, or its composite in the dock. */
    public Composite control() {
        return root;
    }

    /** Whether the tutorial is docked in the IDE rather than a window of its own. */
    public boolean isDocked() {
        return docked;
    }

    /** The lesson's text (tests). */
    public StyledText textWidget() {
        return text;
    }

    /** The page titles, in order (tests). */
    public String[] titles() {
        return index.getItems();
    }

    /** The text shown (tests). */
    public String shownText() {
        return text.getText();
    }

    /** The script of the page shown, or null (tests). */
    public Path script() {
        return script;
    }

    /** The heading and code fonts for the zoom now; the body text's is set by {@link org.parpe.gui.panels.Zoom}. */
    private void fonts() {
        FontData fd = normal.getFontData()[0];
        int points = fd.getHeight() + 2 * zoom;
        heading = new Font(shell.getDisplay(), fd.getName(), Math.round(points * 1.35f), SWT.BOLD);
        Font mono = JFaceResources.getTextFont();
        if (zoom == 0) {
            code = mono;
        } else {
            FontData[] cd = mono.getFontData();
            for (FontData d : cd) {
                d.setHeight(Math.max(6, d.getHeight() + 2 * zoom));
            }
            code = new Font(shell.getDisplay(), cd);
        }
    }

    private void disposeFonts() {
        heading.dispose();
        if (code != JFaceResources.getTextFont()) {
            code.dispose();
        }
    }

    /**
     * Larger ({@code step} 1), smaller (-1) or normal (0) text, as Ctrl + / Ctrl − / Ctrl 0 give it;
     * the page stays where it was scrolled to.
     */
    public void zoom(int step) {
        zoom = org.parpe.gui.panels.Zoom.next(zoom, step);
        int top = text.getTopIndex();
        Font oldHeading = heading;
        Font oldCode = code;
        fonts();
        org.parpe.gui.panels.Zoom.apply(text, normal, zoom);
        org.parpe.gui.panels.Zoom.apply(index, index.getDisplay().getSystemFont(), zoom);
        show(Math.max(0, index.getSelectionIndex()));
        text.setTopIndex(top);
        // Only now: the page drawn before used them.
        oldHeading.dispose();
        if (oldCode != JFaceResources.getTextFont()) {
            oldCode.dispose();
        }
    }

    /** The size of the body text in points (tests). */
    public int points() {
        return text.getFont().getFontData()[0].getHeight();
    }

    /** Shows page {@code i} (ignored when out of range). */
    public void show(int i) {
        if (i < 0 || i >= pages.size()) {
            return;
        }
        index.setSelection(i);
        Markdown.Page page;
        try {
            page = Markdown.parse(CommandNames.forInstall(Files.readString(pages.get(i), StandardCharsets.UTF_8), installed));
        } catch (IOException | RuntimeException e) {
            text.setText(UiMsg.TUTORIAL_CANNOT_READ.text(pages.get(i), e.getMessage()));
            return;
        }
        render(page, pages.get(i).getParent());
        Path dir = pages.get(i).getParent(); // a translated lesson's links start from its language's folder
        script = page.links().stream().filter(l -> l.endsWith(".xml"))
                .map(l -> dir.resolve(l).normalize())
                .filter(Files::isRegularFile).findFirst().orElse(null);
        open.setEnabled(script != null);
        open.setText(script == null ? UiMsg.TUTORIAL_OPEN_SCRIPT.text() : UiMsg.TUTORIAL_OPEN_NAMED.text(script.getFileName()));
        open.getParent().getParent().layout(true, true);
        text.setTopPixel(0);
    }

    private void render(Markdown.Page page, Path dir) {
        disposeImages();
        renderedWidth = text.getClientArea().width;
        links.clear();
        links.addAll(new PageText(text, heading, code, insertCode != null, this::image).show(page, dir));
    }

    /** Follows the link or sends the code under {@code offset}, if any. */
    private void click(int offset) {
        for (PageText.Link t : links) {
            if (t.holds(offset)) {
                if (t.code() != null) {
                    insertCode.accept(t.code());
                } else {
                    follow(t.link());
                }
                return;
            }
        }
    }

    private void follow(String target) {
        if (pictures.contains(target)) {
            PictureWindow.open(shell, Path.of(target));
            return;
        }
        if (target.startsWith("http://") || target.startsWith("https://")) {
            org.eclipse.swt.program.Program.launch(target);
            return;
        }
        Path page = pages.isEmpty() ? null : pages.get(index.getSelectionIndex() < 0 ? 0 : index.getSelectionIndex()).getParent();
        String file = target.replaceFirst("#.*$", "");
        Path p = page == null || file.isEmpty() ? null : page.resolve(file).normalize();
        if (p == null) {
            return;
        }
        int i = pages.indexOf(p);
        if (i >= 0) {
            show(i);
        } else if (file.endsWith(".xml") && Files.isRegularFile(p)) {
            openScript.accept(p);
        } else if (Files.exists(p)) {
            org.eclipse.swt.program.Program.launch(p.toString());
        }
    }

    /** The clickable runs of the page shown: [start, length] each (tests). */
    public List<int[]> clickable() {
        return links.stream().map(t -> new int[] {t.start(), t.length()}).toList();
    }

    /** Clicks the text at {@code offset} (tests). */
    public void clickAt(int offset) {
        click(offset);
    }

    /** The picture at {@code p}, scaled to at most {@value #IMAGE_WIDTH} pixels and the text's width, or null. */
    private Image image(Path linked) {
        Path p = Lessons.picture(linked, Lang.current());
        if (!p.startsWith(folder) || !Files.isRegularFile(p)) {
            return null;
        }
        try {
            ImageData d = new ImageData(p.toString());
            int room = text.getClientArea().width - 40;
            int max = room > 200 ? Math.min(IMAGE_WIDTH, room) : IMAGE_WIDTH;
            if (d.width > max) {
                d = d.scaledTo(max, Math.max(1, d.height * max / d.width));
            }
            Image img = new Image(shell.getDisplay(), d);
            pictures.add(p.toString());
            images.add(img);
            return img;
        } catch (org.eclipse.swt.SWTException e) {
            return null;
        }
    }

    private void disposeImages() {
        images.forEach(Image::dispose);
        images.clear();
        pictures.clear();
    }

    private static String title(Path page) {
        try (Stream<String> lines = Files.lines(page, StandardCharsets.UTF_8)) {
            return lines.filter(l -> l.startsWith("# ")).findFirst().map(l -> l.substring(2).strip())
                    .orElse(page.getFileName().toString().replace(".md", "").toLowerCase(Locale.ROOT));
        } catch (IOException | java.io.UncheckedIOException e) {
            return page.getFileName().toString();
        }
    }
}
