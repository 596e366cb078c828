/**
 * The command line's words in the user's language: {@link org.parpe.cli.text.CliMsg}, the keys of
 * the command line's own messages ({@code CliMessages*.properties}), and the help texts of
 * picocli in German, Spanish and Japanese ({@code Help_*.properties}, keyed as picocli looks them
 * up; English stays in the commands' annotations), with {@link org.parpe.cli.text.HelpKeys} the
 * list of them. The language is chosen by {@link org.parpe.core.text.Lang}.
 */
package org.parpe.cli.text;
