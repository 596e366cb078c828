@echo off
rem PARPE launcher for Windows: builds what it needs on first use (a JDK 17 and Maven on PATH),
rem then runs the command line, or the IDE for "parpe gui ..." and for "parpe" with no arguments.
rem Unlike ./parpe it does not rebuild when sources change: delete the target folders or run
rem "mvn -B package" after editing sources. PARPE_NO_BUILD=1 skips building altogether.
setlocal
set "ROOT=%~dp0"
set "CLI_JAR=%ROOT%parpe-cli\target\parpe.jar"
set "GUI_JAR=%ROOT%parpe-gui\target\parpe-gui.jar"
if "%~1"=="" goto gui
if /i "%~1"=="gui" goto gui

if not "%PARPE_NO_BUILD%"=="1" if not exist "%CLI_JAR%" (
    call :build parpe-cli || exit /b 2
)
java -Djava.awt.headless=true -jar "%CLI_JAR%" %*
exit /b %ERRORLEVEL%

:gui
if not "%PARPE_NO_BUILD%"=="1" if not exist "%GUI_JAR%" (
    call :build parpe-gui || exit /b 2
)
if /i "%~1"=="gui" shift
set "ARGS="
:collect
if "%~1"=="" goto launch
set ARGS=%ARGS% %1
shift
goto collect
:launch
java -jar "%GUI_JAR%" %ARGS%
exit /b %ERRORLEVEL%

:build
echo parpe: building %1 (first use)... 1>&2
pushd "%ROOT%"
call mvn -q -B -DskipTests -Dexec.skip=true -pl %1 -am package 1>&2
set "RC=%ERRORLEVEL%"
popd
if not "%RC%"=="0" (
    echo parpe: build failed; run "mvn -B package" in %ROOT% to see why 1>&2
    exit /b 2
)
exit /b 0
