package org.parpe.gui.grid;

/** The five predefined XML entities and character references, for entries shown in the grid and written back. */
final class Entities {
    private Entities() {
    }

    /** Decodes {@code &lt; &gt; &amp; &quot; &apos;} and {@code &#N;}/{@code &#xN;}; anything else is kept. */
    static String decode(String s) {
        if (s.indexOf('&') < 0) {
            return s;
        }
        StringBuilder out = new StringBuilder(s.length());
        int i = 0;
        while (i < s.length()) {
            int semi = s.charAt(i) == '&' ? s.indexOf(';', i) : -1;
            String ref = semi > i ? s.substring(i + 1, semi) : null;
            String rep = ref == null ? null : switch (ref) {
                case "lt" -> "<";
                case "gt" -> ">";
                case "amp" -> "&";
                case "quot" -> "\"";
                case "apos" -> "'";
                default -> number(ref);
            };
            if (rep == null) {
                out.append(s.charAt(i++));
            } else {
                out.append(rep);
                i = semi + 1;
            }
        }
        return out.toString();
    }

    private static String number(String ref) {
        try {
            if (ref.startsWith("#x") || ref.startsWith("#X")) {
                return new String(Character.toChars(Integer.parseInt(ref.substring(2), 16)));
            }
            if (ref.startsWith("#")) {
                return new String(Character.toChars(Integer.parseInt(ref.substring(1))));
            }
        } catch (IllegalArgumentException e) {
            return null;
        }
        return null;
    }

    /** Escapes the characters an element's text cannot hold as they are. */
    static String encode(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }

    /** Escapes for an attribute value in double quotes. */
    static String encodeAttribute(String s) {
        return encode(s).replace("\"", "&quot;");
    }
}
