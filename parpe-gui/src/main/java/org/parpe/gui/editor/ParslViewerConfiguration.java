package org.parpe.gui.editor;

import java.util.function.BooleanSupplier;
import java.util.function.Function;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.ITextDoubleClickStrategy;
import org.eclipse.jface.text.ITypedRegion;
import org.eclipse.jface.text.TextPresentation;
import org.eclipse.jface.text.IUndoManager;
import org.eclipse.jface.text.TextViewerUndoManager;
import org.eclipse.jface.text.contentassist.ContentAssistant;
import org.eclipse.jface.text.contentassist.IContentAssistant;
import org.eclipse.jface.text.presentation.IPresentationReconciler;
import org.eclipse.jface.text.presentation.PresentationReconciler;
import org.eclipse.jface.text.rules.DefaultDamagerRepairer;
import org.eclipse.jface.text.rules.ITokenScanner;
import org.eclipse.jface.text.source.IAnnotationHover;
import org.eclipse.jface.text.source.ISourceViewer;
import org.eclipse.jface.text.source.SourceViewerConfiguration;
import org.eclipse.swt.SWT;

/** Colouring, content assist, hovers, double-click and undo of the PARSL source viewer. */
final class ParslViewerConfiguration extends SourceViewerConfiguration {
    private final IAnnotationHover hover;
    private final BooleanSupplier plain;
    private final Function<String, NameIndex> names;

    /** {@code plain} says when not to colour (a very large text); {@code names} gives the names a text defines. */
    ParslViewerConfiguration(IAnnotationHover hover, BooleanSupplier plain, Function<String, NameIndex> names) {
        this.hover = hover;
        this.plain = plain;
        this.names = names;
    }

    @Override
    public String[] getConfiguredContentTypes(ISourceViewer sourceViewer) {
        return new String[] {IDocument.DEFAULT_CONTENT_TYPE, XmlScanners.COMMENT, XmlScanners.PROLOG, XmlScanners.TAG};
    }

    @Override
    public IPresentationReconciler getPresentationReconciler(ISourceViewer sourceViewer) {
        PresentationReconciler r = new PresentationReconciler();
        add(r, XmlScanners.tagScanner(), XmlScanners.TAG);
        add(r, XmlScanners.single(XmlScanners.COMMENT_COLOR, SWT.ITALIC), XmlScanners.COMMENT);
        add(r, XmlScanners.single(XmlScanners.PUNCT, SWT.NORMAL), XmlScanners.PROLOG);
        add(r, XmlScanners.textScanner(), IDocument.DEFAULT_CONTENT_TYPE);
        return r;
    }

    private void add(PresentationReconciler r, ITokenScanner scanner, String type) {
        DefaultDamagerRepairer dr = new DefaultDamagerRepairer(scanner) {
            @Override
            public void createPresentation(TextPresentation presentation, ITypedRegion region) {
                if (!plain.getAsBoolean()) {
                    super.createPresentation(presentation, region);
                }
            }
        };
        r.setDamager(dr, type);
        r.setRepairer(dr, type);
    }

    @Override
    public IContentAssistant getContentAssistant(ISourceViewer sourceViewer) {
        ContentAssistant a = new ContentAssistant();
        ParslAssistProcessor p = new ParslAssistProcessor(names);
        for (String type : getConfiguredContentTypes(sourceViewer)) {
            a.setContentAssistProcessor(p, type);
        }
        a.enableAutoActivation(true);
        a.setAutoActivationDelay(300);
        a.enableAutoInsert(true);
        a.setProposalPopupOrientation(IContentAssistant.PROPOSAL_OVERLAY);
        a.setShowEmptyList(false);
        return a;
    }

    @Override
    public ITextDoubleClickStrategy getDoubleClickStrategy(ISourceViewer sourceViewer, String contentType) {
        return new WordDoubleClick();
    }

    @Override
    public IUndoManager getUndoManager(ISourceViewer sourceViewer) {
        return new TextViewerUndoManager(500);
    }

    @Override
    public IAnnotationHover getAnnotationHover(ISourceViewer sourceViewer) {
        return hover;
    }

    @Override
    public int getTabWidth(ISourceViewer sourceViewer) {
        return 2;
    }
}
