/**
 * What the commands read from their options, checked before any work starts: input files
 * ({@link org.parpe.cli.options.Inputs}), output files ({@link org.parpe.cli.options.OutputFile}),
 * {@code --tick}/{@code --duration} and {@code --param}, and the
 * {@link org.parpe.cli.options.UsageException} a bad value ends with (exit code 2).
 */
package org.parpe.cli.options;
