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

    static final Color ELEMENT = new Color(0x1F, 0x4E, 0x9C);
    static final Color ATTRIBUTE = new Color(0x7A, 0x2E, 0x8E);
    static final Color VALUE = new Color(0x1B, 0x7F, 0x3B);
    static final Color COMMENT_COLOR = new Color(0x80, 0x80, 0x80);
    static final Color PUNCT = new Color(0x50, 0x50, 0x60);
    static final Color NUMBER = new Color(0xB0, 0x5A, 0x00);

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
