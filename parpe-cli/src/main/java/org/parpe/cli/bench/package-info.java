/** parpe bench: the Benchmark service interface, the command that runs them, and the core benchmark. */
package org.parpe.cli.bench;
