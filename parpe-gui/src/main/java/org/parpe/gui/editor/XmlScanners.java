package org.parpe.gui.editor;

import org.eclipse.jface.text.TextAttribute;
import org.eclipse.jface.text.rules.ICharacterScanner;
import org.eclipse.jface.text.rules.IPredicateRule;
import org.eclipse.jface.text.rules.IRule;
import org.eclipse.jface.text.rules.IToken;
import org.eclipse.jface.text.rules.IWhitespaceDetector;
import org.eclipse.jface.text.rules.MultiLineRule;
import org.eclipse.jface.text.rules.NumberRule;
import org.eclipse.jface.text.rules.RuleBasedPartitionScanner;
import org.eclipse.jface.text.rules.RuleBasedScanner;
import org.eclipse.jface.text.rules.SingleLineRule;
import org.eclipse.jface.text.rules.Token;
import org.eclipse.jface.text.rules.WhitespaceRule;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.parpe.gui.panels.Theme;

/**
 * The XML colouring of the PARSL editor: a partition scanner that splits the document into
 * comments, processing instructions, tags and text, and one token scanner per partition.
 */
public final class XmlScanners {
    /** Partition of {@code <!-- ... -->}. */
    public static final String COMMENT = "__parsl_comment";
    /** Partition of {@code <?xml ... ?>}. */
    public static final String PROLOG = "__parsl_prolog";
    /** Partition of a start or end tag. */
    public static final String TAG = "__parsl_tag";
    /** The partitions besides the default (text content). */
    public static final String[] TYPES = {COMMENT, PROLOG, TAG};

    // Light and dark variants, chosen by the GTK theme (Theme).
    static final Color ELEMENT = Theme.pick(0x1F4E9C, 0x82B1FF);
    static final Color ATTRIBUTE = Theme.pick(0x7A2E8E, 0xD7A1E8);
    static final Color VALUE = Theme.pick(0x1B7F3B, 0x8FD49F);
    static final Color COMMENT_COLOR = Theme.pick(0x808080, 0x9A9A9A);
    static final Color PUNCT = Theme.pick(0x505060, 0xB8B8C8);
    static final Color NUMBER = Theme.pick(0xB05A00, 0xF2A65A);

    private XmlScanners() {
    }

    /** Splits a document into the partitions above. */
    public static RuleBasedPartitionScanner partitionScanner() {
        RuleBasedPartitionScanner s = new RuleBasedPartitionScanner();
        s.setPredicateRules(new IPredicateRule[] {
            new MultiLineRule("<!--", "-->", new Token(COMMENT), (char) 0, true),
            new MultiLineRule("<?", "?>", new Token(PROLOG), (char) 0, true),
            new MultiLineRule("<", ">", new Token(TAG), (char) 0, true),
        });
        return s;
    }

    /** Colours inside a tag: element name, attribute names, quoted values. */
    public static RuleBasedScanner tagScanner() {
        RuleBasedScanner s = new RuleBasedScanner();
        IToken name = new Token(new TextAttribute(ELEMENT, null, SWT.BOLD));
        IToken attr = new Token(new TextAttribute(ATTRIBUTE));
        IToken value = new Token(new TextAttribute(VALUE));
        s.setRules(new IRule[] {
            new SingleLineRule("\"", "\"", value, '\\'),
            new SingleLineRule("'", "'", value, '\\'),
            new TagNameRule(name),
            new WordRule(attr),
            new WhitespaceRule(new Whitespace()),
        });
        s.setDefaultReturnToken(new Token(new TextAttribute(PUNCT)));
        return s;
    }

    /** Colours in text content (gait tables): numbers stand out. */
    public static RuleBasedScanner textScanner() {
        RuleBasedScanner s = new RuleBasedScanner();
        s.setRules(new IRule[] {new NumberRule(new Token(new TextAttribute(NUMBER)))});
        return s;
    }

    /** One token for the whole partition (comments, prolog). */
    public static RuleBasedScanner single(Color color, int style) {
        RuleBasedScanner s = new RuleBasedScanner();
        s.setDefaultReturnToken(new Token(new TextAttribute(color, null, style)));
        return s;
    }

    static boolean isNameChar(int c) {
        return Character.isLetterOrDigit(c) || c == '_' || c == '-' || c == '.' || c == ':';
    }

    private static final class Whitespace implements IWhitespaceDetector {
        @Override
        public boolean isWhitespace(char c) {
            return Character.isWhitespace(c);
        }
    }

    /** {@code <name}, {@code </name}: the element name after the bracket. */
    private static final class TagNameRule implements IRule {
        private final IToken token;

        TagNameRule(IToken token) {
            this.token = token;
        }

        @Override
        public IToken evaluate(ICharacterScanner scanner) {
            int c = scanner.read();
            if (c != '<') {
                scanner.unread();
                return Token.UNDEFINED;
            }
            c = scanner.read();
            if (c == '/') {
                c = scanner.read();
            }
            while (c != ICharacterScanner.EOF && isNameChar(c)) {
                c = scanner.read();
            }
            scanner.unread();
            return token;
        }
    }

    /** An attribute name. */
    private static final class WordRule implements IRule {
        private final IToken token;

        WordRule(IToken token) {
            this.token = token;
        }

        @Override
        public IToken evaluate(ICharacterScanner scanner) {
            int c = scanner.read();
            if (c == ICharacterScanner.EOF || !isNameChar(c)) {
                scanner.unread();
                return Token.UNDEFINED;
            }
            do {
                c = scanner.read();
            } while (c != ICharacterScanner.EOF && isNameChar(c));
            scanner.unread();
            return token;
        }
    }
}
