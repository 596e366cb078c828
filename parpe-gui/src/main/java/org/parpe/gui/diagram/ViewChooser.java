package org.parpe.gui.diagram;

import java.util.List;
import java.util.function.Consumer;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.RowData;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.parpe.gui.diagram.Projection.View;
import org.parpe.gui.text.PanelMsg;

/**
 * The Diagram pane's choosers: which view, and on which subject (a behavior, automaton or
 * instance, as the view lists them). A choice made asks the pane for a new drawing; the subjects
 * follow each drawing shown. UI thread only.
 */
final class ViewChooser {
    private final Combo viewChoice;
    private final Combo subjectChoice;
    private View view = View.PROGRAM;
    private String subject;

    /**
     * The choosers in {@code bar}; {@code chosen} is told of a view chosen, {@code relayout} of a
     * subject chosen.
     */
    ViewChooser(Composite bar, Consumer<View> chosen, Runnable relayout) {
        Label viewLabel = new Label(bar, SWT.NONE);
        viewLabel.setText(PanelMsg.DIAGRAM_VIEW.text());
        // on the label, not the choosers: a tool tip over a chooser covered its open list (issue 31)
        viewLabel.setToolTipText(PanelMsg.DIAGRAM_VIEW_TIP.text());
        viewChoice = new Combo(bar, SWT.READ_ONLY);
        for (View v : View.values()) {
            viewChoice.add(v.label.text());
        }
        viewChoice.select(0);
        viewChoice.addListener(SWT.Selection, e -> chosen.accept(View.values()[viewChoice.getSelectionIndex()]));
        subjectChoice = new Combo(bar, SWT.READ_ONLY);
        subjectChoice.setLayoutData(new RowData(170, SWT.DEFAULT));
        subjectChoice.addListener(SWT.Selection, e -> {
            subject = subjectChoice.getText();
            relayout.run();
        });
    }

    /** The view chosen. */
    View view() {
        return view;
    }

    /** The subject chosen, or {@code null}: the view's default. */
    String subject() {
        return subject;
    }

    /** Chooses view {@code v} on {@code label} ({@code null}: its default subject). */
    void choose(View v, String label) {
        view = v;
        viewChoice.select(v.ordinal());
        subject = label;
    }

    /** Drawing {@code p} is shown: its subjects to choose from, and the one it shows chosen. */
    void shown(Projection p) {
        // a text that does not load for a moment (an Undo in two steps, typing) keeps the subject chosen
        if (p.subject() != null) {
            subject = p.subject();
        }
        List<String> items = p.subjects();
        if (!items.equals(List.of(subjectChoice.getItems()))) {
            subjectChoice.setItems(items.toArray(String[]::new));
        }
        subjectChoice.setEnabled(!items.isEmpty());
        if (p.subject() != null) {
            subjectChoice.select(items.indexOf(p.subject()));
        }
    }
}
