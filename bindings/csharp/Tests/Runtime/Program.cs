// The C# binding's tests, run under Mono by CTest:
//   mono HedgeTests.exe DATA_DIR SCRATCH_DIR VERSION [FILTER]
// DATA_DIR is the repository's data/ folder, SCRATCH_DIR a writable folder for files the tests write,
// VERSION the project version the native library must report. Exit code: the number of failed
// tests (0: all passed).
using System;
using System.IO;

namespace Hedge.Tests
{
    public static class Context
    {
        public static string DataDir;
        public static string ScratchDir;
        public static string ExpectedVersion;

        public static string Data(string name) { return Path.Combine(DataDir, name); }
        public static string Scratch(string name) { return Path.Combine(ScratchDir, name); }
    }

    public static class Program
    {
        public static int Main(string[] args)
        {
            if (args.Length < 3)
            {
                Console.Error.WriteLine("usage: mono HedgeTests.exe DATA_DIR SCRATCH_DIR VERSION [FILTER]");
                return 2;
            }
            Context.DataDir = args[0];
            Context.ScratchDir = args[1];
            Context.ExpectedVersion = args[2];
            Directory.CreateDirectory(Context.ScratchDir);

            var runner = new Runner();
            runner.AddTests(typeof(Program).Assembly);
            int failed = runner.Run(args.Length > 3 ? args[3] : null);
            return failed > 0 ? 1 : 0;
        }
    }
}
