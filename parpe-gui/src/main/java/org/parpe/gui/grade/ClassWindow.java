package org.parpe.gui.grade;

import org.parpe.gui.text.UiMsg;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.eclipse.jface.resource.JFaceResources;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.DirectoryDialog;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.ProgressBar;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.io.AtomicFiles;
import org.parpe.core.xml.InputFiles;
import org.parpe.gui.panels.FileDialogs;
import org.parpe.gui.view3d.View3D;
import org.parpe.sim.grade.Grading;
import org.parpe.sim.grade.Isolation;
import org.parpe.sim.grade.Report;
import org.parpe.sim.grade.ReportPage;
import org.parpe.sim.grade.Row;
import org.parpe.sim.grade.Students;
import org.parpe.sim.world.Challenge;
import org.parpe.sim.world.ChallengeReader;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldReader;

/**
 * Run → Grade a Class…: a window beside the IDE (not modal). Above, the challenge and the
 * students' folder, each with Open…, and where the report goes (the folder {@code STUDENTS-report}
 * beside the students' folder); Grade and Stop with a progress bar; the ranking; below it, the
 * selected student's run played back from its trace in a 3D view beside that student's script
 * and its problem. Grading is {@code parpe grade}'s ({@link Grading}: a child JVM per student,
 * with the same limits) on a thread of its own, and writes the same report; this class runs on
 * the UI thread only.
 */
public final class ClassWindow {
    private final Shell shell;
    private final Text challengeBox;
    private final Text studentsBox;
    private final Label reportLabel;
    private final Button grade;
    private final Button stop;
    private final ProgressBar progress;
    private final Label counts;
    private final Label message;
    private final RankingTable ranking;
    private final View3D view;
    private final Text problem;
    private final StyledText script;
    private Challenge challenge;
    private World world;
    private Path students;
    private Path report;
    private Thread worker;
    private ReplayPlayer player;

    private ClassWindow(Shell parent) {
        shell = new Shell(parent, SWT.SHELL_TRIM | SWT.MODELESS);
        shell.setText(UiMsg.CLASS_TITLE.text());
        shell.setLayout(new GridLayout(1, false));
        Composite files = row(shell, 3);
        challengeBox = field(files, UiMsg.CLASS_CHALLENGE.text(), this::askChallenge);
        studentsBox = field(files, UiMsg.CLASS_STUDENTS.text(), this::askStudents);
        new Label(files, SWT.NONE).setText(UiMsg.CLASS_REPORT.text());
        reportLabel = new Label(files, SWT.NONE);
        reportLabel.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
        Composite bar = row(shell, 4);
        grade = button(bar, UiMsg.CLASS_GRADE.text(), this::grade);
        stop = button(bar, UiMsg.TOOL_STOP.text(), this::stopGrading);
        progress = new ProgressBar(bar, SWT.HORIZONTAL);
        progress.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        counts = new Label(bar, SWT.NONE);
        counts.setLayoutData(new GridData(320, SWT.DEFAULT));
        message = new Label(shell, SWT.WRAP);
        message.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));

        SashForm split = new SashForm(shell, SWT.VERTICAL);
        split.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        ranking = new RankingTable(split);
        ranking.control().addListener(SWT.Selection, e -> showSelected());
        SashForm beside = new SashForm(split, SWT.HORIZONTAL);
        view = new View3D(beside);
        view.setSource(() -> player == null ? null : player.snapshot());
        view.setOverlay(() -> player == null ? "" : player.caption());
        view.setEmptyText(UiMsg.CLASS_EMPTY.text());
        Composite right = new Composite(beside, SWT.NONE);
        GridLayout gl = new GridLayout(1, false);
        gl.marginWidth = 0;
        gl.marginHeight = 0;
        right.setLayout(gl);
        problem = new Text(right, SWT.MULTI | SWT.READ_ONLY | SWT.WRAP | SWT.V_SCROLL);
        GridData pd = new GridData(SWT.FILL, SWT.TOP, true, false);
        pd.heightHint = 60;
        problem.setLayoutData(pd);
        script = new StyledText(right, SWT.BORDER | SWT.READ_ONLY | SWT.H_SCROLL | SWT.V_SCROLL);
        script.setFont(JFaceResources.getTextFont());
        script.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        split.setWeights(40, 60);
        beside.setWeights(55, 45);
        shell.addListener(SWT.Dispose, e -> {
            stopGrading();
            stopReplay();
        });
        setRunning(false);
    }

    /** Opens a Class window beside {@code parent}, sized for the screen it is on. */
    public static ClassWindow open(Shell parent) {
        ClassWindow w = new ClassWindow(parent);
        org.eclipse.swt.graphics.Rectangle screen = parent.getMonitor().getClientArea();
        w.shell.setBounds(screen.x, screen.y, Math.min(1366, screen.width), Math.min(900, screen.height));
        w.shell.open();
        return w;
    }

    private static Composite row(Composite parent, int columns) {
        Composite c = new Composite(parent, SWT.NONE);
        GridLayout gl = new GridLayout(columns, false);
        gl.marginHeight = 2;
        c.setLayout(gl);
        c.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        return c;
    }

    private static Text field(Composite parent, String label, Runnable ask) {
        new Label(parent, SWT.NONE).setText(label);
        Text t = new Text(parent, SWT.BORDER | SWT.READ_ONLY);
        t.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        button(parent, UiMsg.CLASS_OPEN.text(), ask);
        return t;
    }

    private static Button button(Composite parent, String text, Runnable action) {
        Button b = new Button(parent, SWT.PUSH);
        b.setText(text);
        b.addListener(SWT.Selection, e -> action.run());
        return b;
    }

    private void askChallenge() {
        Path f = FileDialogs.ask(shell, SWT.OPEN, UiMsg.CLASS_OPEN_CHALLENGE.text(), "*.xml", null, null);
        if (f != null) {
            load(f, students);
        }
    }

    private void askStudents() {
        DirectoryDialog d = new DirectoryDialog(shell);
        d.setText(UiMsg.CLASS_STUDENTS_FOLDER.text());
        d.setMessage(UiMsg.CLASS_STUDENTS_FOLDER_TIP.text());
        d.setFilterPath((students != null ? students.toAbsolutePath().getParent() : FileDialogs.start()).toString());
        String chosen = d.open();
        if (chosen != null) {
            load(challenge == null ? null : challenge.file(), Path.of(chosen));
        }
    }

    /**
     * Takes {@code challengeFile} and the students' folder {@code studentsDir} (either may be
     * null: not chosen yet); a challenge with errors is said, with its first error's place.
     */
    public void load(Path challengeFile, Path studentsDir) {
        if (challengeFile != null && (challenge == null || !challenge.file().equals(challengeFile))) {
            DiagnosticList found = new DiagnosticList();
            Challenge c = ChallengeReader.read(challengeFile, found);
            World w = c == null ? null : WorldReader.read(c.world(), found);
            challengeBox.setText(challengeFile.toString());
            challenge = w == null ? null : c;
            world = w;
            say(w == null ? (found.all().isEmpty() ? UiMsg.CLASS_CHALLENGE_ERRORS.text(challengeFile)
                    : found.all().get(0).format()) : "");
            shell.setText(UiMsg.CLASS_TITLE_NAMED.text(challengeFile.getFileName()));
        }
        if (studentsDir != null) {
            students = studentsDir;
            studentsBox.setText(studentsDir.toString());
            Path abs = studentsDir.toAbsolutePath().normalize();
            report = abs.resolveSibling(abs.getFileName() + "-report");
            reportLabel.setText(report.toString());
        }
        setRunning(false);
    }

    private void grade() {
        if (challenge == null || students == null || running()) {
            return;
        }
        String why = Grading.prepare(report, students, UiMsg.CLASS_REPORT_FOLDER.text());
        List<Students.Student> list;
        try {
            list = why == null ? Students.of(students) : List.of();
        } catch (IOException e) {
            why = UiMsg.CLASS_CANNOT_LIST.text(students, e.getMessage());
            list = List.of();
        }
        if (why != null) {
            say(why);
            return;
        }
        stopReplay();
        ranking.show(List.of());
        progress.setMaximum(Math.max(1, list.size()));
        progress.setSelection(0);
        counts.setText(UiMsg.CLASS_GRADED.text(0, list.size()));
        say("");
        Grading g = new Grading(challenge.file(), challenge, students, report, Isolation.Limits.DEFAULTS);
        int jobs = Runtime.getRuntime().availableProcessors();
        List<Students.Student> all = list;
        Challenge c = challenge;
        World w = world;
        worker = new Thread(() -> work(g, all, jobs, c, w), "parpe-class-grading");
        worker.setDaemon(true);
        worker.start();
        setRunning(true);
    }

    /** On the grading thread: runs the class, writes the report, tells the UI thread. */
    private void work(Grading g, List<Students.Student> list, int jobs, Challenge c, World w) {
        String end;
        List<Row> rows = null;
        try {
            rows = g.run(list, jobs, (done, total, s) -> ui(() -> {
                progress.setSelection(done);
                counts.setText(UiMsg.CLASS_GRADED_NAME.text(done, total, s.name().replaceAll("\\p{Cntrl}", "?")));
            }));
            AtomicFiles.write(g.out().resolve("report.csv"), Report.csv(rows));
            AtomicFiles.write(g.out().resolve("report.html"), ReportPage.html(rows, c, w));
            end = UiMsg.CLASS_REPORT_IN.text(Report.summary(rows, c), g.out().resolve("report.html"));
        } catch (InterruptedException e) {
            end = UiMsg.CLASS_STOPPED.text();
        } catch (IOException e) {
            end = UiMsg.CLASS_CANNOT_WRITE_REPORT.text(g.out(), e.getMessage());
        }
        List<Row> shown = rows;
        String said = end;
        ui(() -> {
            if (shown != null) {
                ranking.show(shown);
            }
            worker = null;
            say(said);
            setRunning(false);
        });
    }

    private void ui(Runnable r) {
        if (!shell.isDisposed()) {
            shell.getDisplay().asyncExec(() -> {
                if (!shell.isDisposed()) {
                    r.run();
                }
            });
        }
    }

    private void stopGrading() {
        Thread t = worker;
        if (t != null) {
            t.interrupt(); // Grading kills the children under way
        }
    }

    /** Shows the selected student's script and problem, and replays its run if it has a trace. */
    private void showSelected() {
        Row r = ranking.selected();
        if (r == null) {
            return;
        }
        problem.setText(r.student().name().replaceAll("\\p{Cntrl}", "?")
                + (r.outcome().reason().isEmpty() ? UiMsg.CLASS_RANK_SCORE.text(r.rank(),
                String.format(Locale.ROOT, "%.1f", r.outcome().score()), r.outcome().parts()) : ":\n" + r.outcome().reason()));
        script.setText(scriptText(r.student()));
        stopReplay();
        view.clear();
        if (!r.trace().isEmpty() && challenge != null) {
            player = new ReplayPlayer(shell.getDisplay(), r.student().name().replaceAll("\\p{Cntrl}", "?"), challenge, world,
                    report.resolve(r.trace()), this::say);
            view.resetView();
            view.startAnimation();
        }
    }

    /** The student's script as text, or why it is not shown (it is read as an input file: a huge one is refused). */
    private String scriptText(Students.Student s) {
        if (s.script() == null) {
            return "";
        }
        Path f = students.resolve(s.script());
        try {
            InputFiles.check(f);
            return Files.readString(f, java.nio.charset.StandardCharsets.UTF_8);
        } catch (IOException e) {
            return UiMsg.CLASS_CANNOT_SHOW.text(s.script(), e.getMessage());
        }
    }

    private void stopReplay() {
        if (player != null) {
            player.stop();
            player = null;
        }
    }

    private void say(String text) {
        message.setText(text);
        shell.layout(true, true);
    }

    private void setRunning(boolean running) {
        grade.setEnabled(!running && challenge != null && students != null);
        stop.setEnabled(running);
    }

    /** The window. */
    public Shell shell() {
        return shell;
    }

    /** Brings the window to the front. */
    public void activate() {
        shell.setActive();
    }

    /** Whether a grading is under way. */
    public boolean running() {
        return worker != null;
    }

    /** The controls a test presses and reads, as a user would. */
    Controls controls() {
        return new Controls(grade, stop, progress, ranking, view, script, problem);
    }

    /** The window's controls (for tests). */
    record Controls(Button grade, Button stop, ProgressBar progress, RankingTable ranking, View3D view,
            StyledText script, Text problem) {
    }

    String message() {
        return message.getText();
    }

    ReplayPlayer player() {
        return player;
    }
}
