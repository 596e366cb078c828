package org.parpe.gui.panels;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.eclipse.jface.dialogs.IDialogConstants;
import org.eclipse.jface.dialogs.TitleAreaDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Parameter;
import org.parpe.gui.text.ToolMsg;

/**
 * The dialog generated from {@code <parameters>} before a run: one number box per parameter
 * with its label and bounds, checked as the user types; Run is enabled only when every value
 * is a number within its bounds.
 */
public final class ParametersDialog extends TitleAreaDialog {
    private final List<Parameter> parameters;
    private final Map<String, Double> initial;
    private final Map<String, Text> boxes = new LinkedHashMap<>();
    private Map<String, Double> result;

    /**
     * @param parameters the declared parameters
     * @param initial    the values to show (last values used, else the defaults)
     */
    public ParametersDialog(Shell parent, List<Parameter> parameters, Map<String, Double> initial) {
        super(parent);
        this.parameters = parameters;
        this.initial = initial;
    }

    @Override
    protected void configureShell(Shell shell) {
        super.configureShell(shell);
        shell.setText(ToolMsg.PARAMS_TITLE.text());
    }

    @Override
    protected Control createDialogArea(Composite parent) {
        Composite area = (Composite) super.createDialogArea(parent);
        setTitle(ToolMsg.PARAMS_HEADING.text());
        setMessage(ToolMsg.PARAMS_MESSAGE.text());
        Composite grid = new Composite(area, SWT.NONE);
        grid.setLayout(new GridLayout(3, false));
        grid.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        for (Parameter p : parameters) {
            new Label(grid, SWT.NONE).setText(p.displayLabel());
            Text t = new Text(grid, SWT.BORDER | SWT.SINGLE);
            t.setText(Numbers.format(initial.getOrDefault(p.name(), p.value())));
            t.setLayoutData(new GridData(120, SWT.DEFAULT));
            t.addListener(SWT.Modify, e -> validate());
            Label bounds = new Label(grid, SWT.NONE);
            bounds.setText(bounds(p));
            bounds.setForeground(grid.getDisplay().getSystemColor(SWT.COLOR_DARK_GRAY));
            boxes.put(p.name(), t);
        }
        return area;
    }

    @Override
    protected void createButtonsForButtonBar(Composite parent) {
        createButton(parent, IDialogConstants.OK_ID, ToolMsg.PARAMS_RUN.text(), true);
        createButton(parent, IDialogConstants.CANCEL_ID, IDialogConstants.CANCEL_LABEL, false);
        validate();
    }

    private static String bounds(Parameter p) {
        String lo = p.min() == null ? "" : Numbers.format(p.min()) + " \u2264 ";
        String hi = p.max() == null ? "" : " \u2264 " + Numbers.format(p.max());
        return ToolMsg.PARAMS_BOUNDS.text(lo + p.name() + hi, Numbers.format(p.value()));
    }

    /** The first problem with the values typed, or null. */
    private String problem() {
        for (Parameter p : parameters) {
            Text t = boxes.get(p.name());
            if (t == null) {
                continue;
            }
            Double v = Numbers.parsePlain(t.getText());
            String err = v == null ? ToolMsg.PARAMS_NOT_A_NUMBER.text(p.displayLabel(), t.getText().trim()) : p.check(v);
            if (err != null) {
                return err;
            }
        }
        return null;
    }

    private void validate() {
        String err = problem();
        setErrorMessage(err);
        if (getButton(IDialogConstants.OK_ID) != null) {
            getButton(IDialogConstants.OK_ID).setEnabled(err == null);
        }
    }

    @Override
    protected void okPressed() {
        if (problem() != null) {
            return;
        }
        result = new LinkedHashMap<>();
        boxes.forEach((name, t) -> result.put(name, Numbers.parsePlain(t.getText())));
        super.okPressed();
    }

    /** The values entered, or null if the dialog was cancelled. */
    public Map<String, Double> values() {
        return result;
    }
}
