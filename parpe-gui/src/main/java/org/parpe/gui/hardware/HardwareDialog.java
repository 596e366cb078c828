package org.parpe.gui.hardware;


import org.parpe.gui.text.UiMsg;
import org.parpe.gui.panels.TitleWidths;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Spinner;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableItem;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.io.OutputPlan;
import org.parpe.serial.link.SerialLink;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ProfileReader;
import org.parpe.serial.servo.profile.ServoMapping;

/**
 * Run → Hardware…: connect to a servo bus (port, protocol, baud) or scan for one, see the servos
 * with their positions and faults, make them limp or hold, jog one (a number box that starts at
 * the servo's position and moves it 1° an arrow click, 5° a page, at a limited speed), and save a
 * starter hardware profile that becomes the tool bar's profile. The bus belongs to a
 * {@link HardwareSession} (its own thread); this class only touches widgets, on the UI thread.
 * Closing the dialog closes the bus.
 */
public final class HardwareDialog {
    private static final String ANY = "any";
    private static final int[] BAUDS = {57_600, 115_200, 1_000_000, 2_000_000, 3_000_000, 4_000_000, 500_000, 9_600};
    /** The jog box counts tenths of a degree. */
    private static final int STEPS_PER_DEG = 10;
    /** One arrow click or arrow key of the jog box: 1°; Page Up/Down: 5°. */
    private static final int JOG_STEP = STEPS_PER_DEG;
    private static final int JOG_PAGE = 5 * STEPS_PER_DEG;

    private final HardwareHost ide;
    private final Shell shell;
    private final Combo port;
    private final Combo protocol;
    private final Combo baud;
    private final Table table;
    private final Spinner jogBox;
    private final Label jogValue;
    private final Label message;
    private final HardwareSession session;
    private List<HardwareSession.Servo> servos = List.of();
    /** The row the jog box was set up for (−1: none). */
    private int jogRow = -1;
    /** The selected servo's position is not known yet: the jog box is set up when it is. */
    private boolean jogAwaitsPosition;

    private HardwareDialog(HardwareHost ide) {
        this.ide = ide;
        shell = new Shell(ide.shell(), SWT.DIALOG_TRIM | SWT.RESIZE);
        shell.setText(UiMsg.HW_TITLE.text());
        // Reports reach widgets through asyncExec, after the constructor has made them.
        session = new HardwareSession(new ToUi());
        shell.setLayout(new GridLayout(1, false));
        Composite top = row(9);
        label(top, UiMsg.TOOL_PORT.text());
        port = portBox(top);
        label(top, UiMsg.HW_PROTOCOL.text());
        protocol = anyOr(new Combo(top, SWT.READ_ONLY),
                java.util.Arrays.stream(ServoProtocol.values()).map(ServoProtocol::key).toList());
        label(top, UiMsg.HW_BAUD.text());
        baud = anyOr(new Combo(top, SWT.DROP_DOWN), java.util.Arrays.stream(BAUDS).mapToObj(String::valueOf).toList());
        baud.setLayoutData(width(100));
        button(top, UiMsg.HW_CONNECT.text(), UiMsg.HW_CONNECT_TIP.text(), this::connect);
        button(top, UiMsg.HW_SCAN.text(), UiMsg.HW_SCAN_TIP.text(), () -> {
            protocol.select(0);
            baud.select(0);
            connect();
        });

        table = servoTable();

        torqueButtons();

        Composite jog = row(3);
        label(jog, UiMsg.HW_JOG.text());
        jogBox = jogSpinner(jog);
        jogValue = new Label(jog, SWT.NONE);
        jogValue.setLayoutData(width(260));

        message = new Label(shell, SWT.WRAP);
        GridData md = new GridData(SWT.FILL, SWT.CENTER, true, false);
        md.widthHint = 640;
        md.heightHint = 40;
        message.setLayoutData(md);
        message.setText(UiMsg.HW_START.text());

        Composite bottom = row(2);
        button(bottom, UiMsg.HW_SAVE_PROFILE.text(), UiMsg.HW_SAVE_PROFILE_TIP.text(),
                this::chooseProfileFile);
        button(bottom, UiMsg.BUTTON_CLOSE.text(), UiMsg.HW_CLOSE_TIP.text(), shell::close);

        shell.addListener(SWT.Dispose, e -> {
            session.close();
            ide.setHardwareHeld(null);
            ide.hardwareGone();
        });
        listPorts();
        shell.pack();
        shell.setSize(Math.max(760, shell.getSize().x), Math.max(520, shell.getSize().y));
        place();
        shell.open();
    }

    /** The serial port, typed or picked from the devices present when the list opens. */
    private Combo portBox(Composite parent) {
        Combo c = new Combo(parent, SWT.DROP_DOWN);
        c.setLayoutData(width(170));
        c.setText(ide.portChoice().port());
        c.setToolTipText(UiMsg.HW_PORT_TIP.text());
        c.addListener(SWT.MouseDown, e -> listPorts());
        return c;
    }

    /** {@code box} offering {@value #ANY} and then {@code choices}, {@value #ANY} chosen. */
    private static Combo anyOr(Combo box, List<String> choices) {
        box.add(ANY);
        choices.forEach(box::add);
        box.select(0);
        return box;
    }

    /** The servos found: id, model, position, torque, status. */
    private Table servoTable() {
        Table t = new Table(shell, SWT.BORDER | SWT.FULL_SELECTION | SWT.SINGLE);
        t.setHeaderVisible(true);
        t.setLinesVisible(true);
        GridData td = new GridData(SWT.FILL, SWT.FILL, true, true);
        td.heightHint = 220;
        t.setLayoutData(td);
        TitleWidths.column(t, SWT.LEFT, UiMsg.HW_COL_ID.text(), 50);
        TitleWidths.column(t, SWT.LEFT, UiMsg.HW_COL_MODEL.text(), 170);
        TitleWidths.column(t, SWT.LEFT, UiMsg.HW_COL_POSITION.text(), 100);
        TitleWidths.column(t, SWT.LEFT, UiMsg.HW_COL_TORQUE.text(), 80);
        TitleWidths.column(t, SWT.LEFT, UiMsg.HW_COL_STATUS.text(), 260);
        t.addListener(SWT.Selection, e -> selected());
        return t;
    }

    /** Limp or hold all servos, or the selected one. */
    private void torqueButtons() {
        Composite torque = row(5);
        button(torque, UiMsg.HW_LIMP_ALL.text(), UiMsg.HW_LIMP_ALL_TIP.text(), () -> session.torque(-1, false));
        button(torque, UiMsg.HW_HOLD_ALL.text(), UiMsg.HW_HOLD_ALL_TIP.text(), () -> session.torque(-1, true));
        button(torque, UiMsg.HW_LIMP.text(), UiMsg.HW_LIMP_TIP.text(), () -> onSelected(r -> session.torque(r, false)));
        button(torque, UiMsg.HW_HOLD.text(), UiMsg.HW_HOLD_TIP.text(),
                () -> onSelected(r -> session.torque(r, true)));
    }

    /** The jog box: the selected servo's target, off until a servo's position is known. */
    private Spinner jogSpinner(Composite parent) {
        Spinner box = new Spinner(parent, SWT.BORDER);
        box.setLayoutData(width(90));
        box.setEnabled(false);
        box.setToolTipText(UiMsg.HW_JOG_TIP.text((int) HardwareSession.JOG_DEG_PER_S));
        box.addListener(SWT.Selection, e -> jog());
        box.addListener(SWT.DefaultSelection, e -> jog());
        return box;
    }

    /** Over the IDE window, clear of the Pose panel where it can be ({@link DialogPlace}). */
    private void place() {
        org.eclipse.swt.widgets.Control panels = ide.posePanel().getParent();
        org.eclipse.swt.graphics.Rectangle at = DialogPlace.over(ide.shell().getBounds(),
                ide.shell().getMonitor().getClientArea(), shell.getSize(),
                ide.shell().getDisplay().map(panels.getParent(), null, panels.getBounds()));
        shell.setLocation(at.x, at.y);
    }

    /** Fills the port list, keeping what is typed; with no adapter found the dialog says so. */
    private void listPorts() {
        String typed = port.getText();
        List<String> found = SerialLink.availablePorts();
        port.setItems(found.toArray(new String[0]));
        port.setText(typed);
        if (found.isEmpty() && message != null && servos.isEmpty()) {
            show(UiMsg.HW_NO_ADAPTER.text(), false);
        }
    }

    /** Opens the dialog, or brings the open one to the front. */
    public static HardwareDialog open(HardwareHost ide) {
        HardwareDialog d = ide.hardwareDialog();
        if (d != null && !d.shell.isDisposed()) {
            d.shell.setActive();
            return d;
        }
        d = new HardwareDialog(ide);
        ide.setHardwareDialog(d);
        return d;
    }

    private Composite row(int columns) {
        Composite c = new Composite(shell, SWT.NONE);
        GridLayout gl = new GridLayout(columns, false);
        gl.marginWidth = 0;
        gl.marginHeight = 0;
        c.setLayout(gl);
        c.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        return c;
    }

    private static void label(Composite parent, String text) {
        new Label(parent, SWT.NONE).setText(text);
    }

    private static GridData width(int w) {
        GridData gd = new GridData(SWT.LEFT, SWT.CENTER, false, false);
        gd.widthHint = w;
        return gd;
    }

    private static Button button(Composite parent, String text, String tip, Runnable action) {
        Button b = new Button(parent, SWT.PUSH);
        b.setText(text);
        b.setToolTipText(tip);
        b.addListener(SWT.Selection, e -> action.run());
        return b;
    }

    /** Connect with what the boxes say; a wrong baud is said in the dialog. */
    void connect() {
        String p = port.getText().trim();
        if (p.isEmpty()) {
            show(UiMsg.HW_GIVE_PORT.text(), true);
            return;
        }
        ServoProtocol proto = protocol.getSelectionIndex() <= 0 ? null : ServoProtocol.of(protocol.getText());
        Integer rate = null;
        String b = baud.getText().trim();
        if (!b.isEmpty() && !b.equalsIgnoreCase(ANY)) {
            try {
                rate = Integer.parseInt(b);
            } catch (NumberFormatException e) {
                rate = -1;
            }
            if (rate <= 0) {
                show(UiMsg.HW_BAD_BAUD.text(b), true);
                return;
            }
        }
        ide.portChoice().setPort(p);
        setServos(List.of());
        show(proto == null || rate == null ? UiMsg.HW_SCANNING_PORT.text(p) : UiMsg.HW_CONNECTING_NOW.text(), false);
        session.connect(p, proto, rate, null);
    }

    private void onSelected(java.util.function.IntConsumer action) {
        int r = table.getSelectionIndex();
        if (r < 0) {
            show(UiMsg.HW_SELECT_SERVO.text(), true);
            return;
        }
        action.accept(r);
    }

    /**
     * A servo was selected: the jog box takes its present position and the model's range, narrowed
     * to the joint limits of the tool bar's hardware profile when it maps this servo, else to those
     * a starter profile would give it (±90°), rounded inwards to tenths; it stays off while the
     * position is not known or no angle is allowed.
     */
    private void selected() {
        int r = table.getSelectionIndex();
        ServoModel m = r < 0 || r >= servos.size() ? null : servos.get(r).model();
        double deg = m == null ? Double.NaN : servos.get(r).degrees();
        jogRow = m == null ? -1 : r;
        jogAwaitsPosition = m != null && Double.isNaN(deg);
        if (m == null || Double.isNaN(deg)) {
            jogBox.setEnabled(false);
            jogValue.setText(m == null ? "" : UiMsg.HW_POSITION_UNKNOWN.text());
            return;
        }
        double min = m.minDegrees();
        double max = m.maxDegrees();
        ServoMapping limits = profileLimits(servos.get(r).id(), m);
        String whose = limits == null ? UiMsg.HW_STARTER_LIMITS.text() : UiMsg.HW_MODULE_LIMITS.text(limits.module());
        if (limits == null) {
            limits = ServoMapping.starter(servos.get(r).id(), servos.get(r).id(), m, SourcePos.NONE);
        }
        double a = limits.servoAngle(limits.min());
        double b = limits.servoAngle(limits.max());
        min = Math.max(min, Math.min(a, b));
        max = Math.min(max, Math.max(a, b));
        int lo = (int) Math.ceil(min * STEPS_PER_DEG - 1e-9);
        int hi = (int) Math.floor(max * STEPS_PER_DEG + 1e-9);
        jogBox.setEnabled(lo <= hi);
        if (lo > hi) {
            jogValue.setText(UiMsg.HW_NO_ANGLE_WITHIN.text(whose));
            return;
        }
        int at = (int) Math.max(lo, Math.min(hi, Math.round(deg * STEPS_PER_DEG)));
        jogBox.setValues(at, lo, hi, 1, JOG_STEP, JOG_PAGE);
        jogValue.setText(String.format(Locale.ROOT, "%s %s..%s", whose, degrees(lo / (double) STEPS_PER_DEG),
                degrees(hi / (double) STEPS_PER_DEG)));
    }

    /**
     * The mapping of servo {@code id} (of {@code model}'s protocol) in the tool bar's hardware
     * profile, or null when there is no profile, it does not load, or it does not map the servo.
     */
    private ServoMapping profileLimits(int id, ServoModel model) {
        String file = ide.portChoice().hardwareProfile();
        if (file == null) {
            return null;
        }
        HardwareProfile p = ProfileReader.read(Path.of(file), new DiagnosticList());
        if (p == null || p.protocol() != model.protocol()) {
            return null;
        }
        for (ServoMapping s : p.servos()) {
            if (s.servo() == id) {
                return s;
            }
        }
        return null;
    }

    private void jog() {
        int r = table.getSelectionIndex();
        if (r < 0 || r != jogRow || r >= servos.size() || servos.get(r).model() == null || !jogBox.isEnabled()) {
            return;
        }
        double deg = jogBox.getSelection() / (double) STEPS_PER_DEG;
        jogValue.setText(UiMsg.HW_MOVING_TO.text(degrees(deg)));
        session.jog(r, deg);
    }

    private void chooseProfileFile() {
        Path f = org.parpe.gui.panels.FileDialogs.ask(shell, SWT.SAVE, UiMsg.HW_SAVE_PROFILE_TITLE.text(), "*.xml", "hardware.xml", null);
        if (f != null) {
            saveProfile(f);
        }
    }

    /** Writes the starter profile (on the bus thread) and selects it in the tool bar's Profile box. */
    public void saveProfile(Path file) {
        for (Path open : ide.openFiles()) {
            if (OutputPlan.sameFile(open, file)) {
                show(UiMsg.HW_PROFILE_OVER_SCRIPT.text(file.getFileName()), true);
                return;
            }
        }
        session.saveProfile(file, f -> ui(() -> ide.portChoice().setHardwareProfile(f.toString())));
    }

    private void show(String text, boolean error) {
        message.setText(text);
        message.setForeground(error ? shell.getDisplay().getSystemColor(SWT.COLOR_DARK_RED) : null);
    }

    private void setServos(List<HardwareSession.Servo> list) {
        int sel = table.getSelectionIndex();
        boolean sameRows = list.size() == servos.size();
        servos = list;
        if (!sameRows) {
            table.removeAll();
            for (int i = 0; i < list.size(); i++) {
                new TableItem(table, SWT.NONE);
            }
        }
        for (int i = 0; i < list.size(); i++) {
            HardwareSession.Servo s = list.get(i);
            table.getItem(i).setText(new String[] {String.valueOf(s.id()),
                s.model() == null ? UiMsg.HW_MODEL_UNKNOWN_ROW.text(s.modelNumber()) : s.model().label(),
                Double.isNaN(s.degrees()) ? "?" : degrees(s.degrees()), s.torque() == null ? "?" : (s.torque() ? UiMsg.HW_TORQUE_HOLD : UiMsg.HW_TORQUE_LIMP).text(),
                s.status().isEmpty() ? UiMsg.HW_STATUS_OK.text() : s.status()});
        }
        if (!sameRows) {
            selected();
        } else if (sel >= 0) {
            table.setSelection(sel);
            if (jogAwaitsPosition && sel == jogRow) {
                selected();
            }
        }
    }

    private static String degrees(double d) {
        return String.format(Locale.ROOT, "%.1f\u00b0", d);
    }

    /** Runs {@code r} on the UI thread unless the dialog has gone. */
    private void ui(Runnable r) {
        Display display = shell.getDisplay();
        if (display.isDisposed()) {
            return;
        }
        try {
            display.asyncExec(() -> {
                if (!shell.isDisposed()) {
                    r.run();
                }
            });
        } catch (org.eclipse.swt.SWTException e) {
            // The display was disposed between the check and the call.
        }
    }

    /** The session's reports, moved to the UI thread. */
    private final class ToUi implements HardwareSession.Listener {
        @Override
        public void message(String text, boolean error) {
            ui(() -> show(text, error));
        }

        @Override
        public void connected(List<HardwareSession.Servo> list, ServoProtocol p, int rate, String device) {
            ui(() -> {
                setServos(list);
                if (!list.isEmpty()) {
                    // After a scan the boxes say what was found, so Connect and Save use it.
                    protocol.select(protocol.indexOf(p.key()));
                    baud.setText(String.valueOf(rate));
                }
                ide.setHardwareHeld(list.isEmpty() ? null : list.size() == 1
                        ? UiMsg.HW_HELD_ONE.text(p.key().toUpperCase(Locale.ROOT), device)
                        : UiMsg.HW_HELD_N.text(list.size(), p.key().toUpperCase(Locale.ROOT), device));
            });
        }

        @Override
        public void updated(List<HardwareSession.Servo> list) {
            ui(() -> setServos(list));
        }
    }

    /** The servos as last read (positions polled every few hundred ms); empty when none is connected. */
    public List<HardwareSession.Servo> servos() {
        return servos;
    }

    /** The bus session (the Pose panel makes servos limp, reads and moves them through it). */
    public HardwareSession session() {
        return session;
    }

    /** The dialog's window (the Pose panel checks it is still open). */
    public Shell shell() {
        return shell;
    }

    /**
     * The widgets as a user sees them (tests read and drive them on the UI thread).
     *
     * @param table    the servos found
     * @param jogBox   the jog box of the selected servo
     * @param jogValue the line under the jog box (its limits, or why it is off)
     * @param message  the status line
     * @param port     the serial port box
     * @param protocol the bus protocol box
     * @param baud     the baud rate box
     */
    public record Widgets(Table table, Spinner jogBox, Label jogValue, Label message, Combo port, Combo protocol,
                          Combo baud) {
    }

    public Widgets widgets() {
        return new Widgets(table, jogBox, jogValue, message, port, protocol, baud);
    }
}
