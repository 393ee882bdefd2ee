// A small test harness: assertions that name the file and line of the failed check, a [Test]
// attribute, and a runner that finds the marked tests, prints each test's name and result and
// returns the number of failed tests.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Runtime.CompilerServices;
using System.Text;

namespace Hedge.Tests
{
    /// <summary>A failed check: where and what.</summary>
    public sealed class CheckFailed : Exception
    {
        public CheckFailed(string message) : base(message) { }
    }

    public static class Check
    {
        static int checks;

        /// <summary>Checks made so far (all tests).</summary>
        public static int Count { get { return checks; } }

        static void Fail(string file, int line, string message)
        {
            throw new CheckFailed(Path.GetFileName(file) + ":" + line + ": " + message);
        }

        public static void True(bool condition, string what = "", [CallerFilePath] string file = "",
                                [CallerLineNumber] int line = 0)
        {
            ++checks;
            if (!condition) Fail(file, line, "check failed" + (what.Length > 0 ? ": " + what : ""));
        }

        public static void False(bool condition, string what = "", [CallerFilePath] string file = "",
                                 [CallerLineNumber] int line = 0)
        {
            ++checks;
            if (condition) Fail(file, line, "expected false" + (what.Length > 0 ? ": " + what : ""));
        }

        public static void Equal<T>(T expected, T actual, string what = "", [CallerFilePath] string file = "",
                                    [CallerLineNumber] int line = 0)
        {
            ++checks;
            if (!EqualityComparer<T>.Default.Equals(expected, actual))
                Fail(file, line, "expected " + Show(expected) + ", got " + Show(actual) +
                                 (what.Length > 0 ? " (" + what + ")" : ""));
        }

        public static void Near(double expected, double actual, double tolerance, string what = "",
                                [CallerFilePath] string file = "", [CallerLineNumber] int line = 0)
        {
            ++checks;
            if (!(Math.Abs(expected - actual) <= tolerance))
                Fail(file, line, "expected " + expected.ToString("R") + " +- " + tolerance + ", got " +
                                 actual.ToString("R") + (what.Length > 0 ? " (" + what + ")" : ""));
        }

        /// <summary>The first count entries of two arrays are equal.</summary>
        public static void Same<T>(T[] expected, T[] actual, int count, string what = "",
                                   [CallerFilePath] string file = "", [CallerLineNumber] int line = 0)
        {
            ++checks;
            if (expected.Length < count || actual.Length < count)
                Fail(file, line, "arrays shorter than " + count + (what.Length > 0 ? " (" + what + ")" : ""));
            var cmp = EqualityComparer<T>.Default;
            for (int i = 0; i < count; ++i)
                if (!cmp.Equals(expected[i], actual[i]))
                    Fail(file, line, "entry " + i + ": expected " + Show(expected[i]) + ", got " + Show(actual[i]) +
                                     (what.Length > 0 ? " (" + what + ")" : ""));
        }

        public static void Contains(string text, string part, string what = "", [CallerFilePath] string file = "",
                                    [CallerLineNumber] int line = 0)
        {
            ++checks;
            if (text == null || text.IndexOf(part, StringComparison.Ordinal) < 0)
                Fail(file, line, "\"" + text + "\" does not contain \"" + part + "\"" +
                                 (what.Length > 0 ? " (" + what + ")" : ""));
        }

        /// <summary>The action throws a HedgeException with this status; returns it.</summary>
        public static HedgeException Throws(HedgeStatus status, Action action, string what = "",
                                            [CallerFilePath] string file = "", [CallerLineNumber] int line = 0)
        {
            ++checks;
            try
            {
                action();
            }
            catch (HedgeException e)
            {
                if (e.Status != status)
                    Fail(file, line, "expected HedgeException " + status + ", got " + e.Status + ": " + e.Message +
                                     (what.Length > 0 ? " (" + what + ")" : ""));
                if (string.IsNullOrEmpty(e.Message)) Fail(file, line, "HedgeException without a message");
                return e;
            }
            catch (Exception e)
            {
                Fail(file, line, "expected HedgeException " + status + ", got " + e.GetType().Name + ": " + e.Message +
                                 (what.Length > 0 ? " (" + what + ")" : ""));
            }
            Fail(file, line, "expected HedgeException " + status + ", nothing thrown" +
                             (what.Length > 0 ? " (" + what + ")" : ""));
            return null;
        }

        /// <summary>The action throws an exception of type E (or derived); returns it.</summary>
        public static E ThrowsType<E>(Action action, string what = "", [CallerFilePath] string file = "",
                                      [CallerLineNumber] int line = 0) where E : Exception
        {
            ++checks;
            try
            {
                action();
            }
            catch (E e)
            {
                return e;
            }
            catch (Exception e)
            {
                Fail(file, line, "expected " + typeof(E).Name + ", got " + e.GetType().Name + ": " + e.Message +
                                 (what.Length > 0 ? " (" + what + ")" : ""));
            }
            Fail(file, line, "expected " + typeof(E).Name + ", nothing thrown" + (what.Length > 0 ? " (" + what + ")" : ""));
            return null;
        }

        /// <summary>Validate() reports no problems.</summary>
        public static void Valid(HalfEdgeMesh mesh, string what = "", [CallerFilePath] string file = "",
                                 [CallerLineNumber] int line = 0)
        {
            ++checks;
            string[] problems = mesh.Validate();
            if (problems.Length > 0)
                Fail(file, line, "Validate() found " + problems.Length + " problem(s)" +
                                 (what.Length > 0 ? " (" + what + ")" : "") + ":\n    " +
                                 string.Join("\n    ", problems));
        }

        static string Show<T>(T value)
        {
            if (value == null) return "null";
            if (value is float) return ((float)(object)value).ToString("R");
            if (value is double) return ((double)(object)value).ToString("R");
            return value.ToString();
        }
    }

    /// <summary>Marks a static, parameterless method as a test; the runner names it Class.Method.</summary>
    [AttributeUsage(AttributeTargets.Method)]
    public sealed class TestAttribute : Attribute
    {
    }

    /// <summary>Runs named tests, printing each one's name and outcome.</summary>
    public sealed class Runner
    {
        readonly List<KeyValuePair<string, Action>> tests = new List<KeyValuePair<string, Action>>();

        public void Add(string name, Action test) { tests.Add(new KeyValuePair<string, Action>(name, test)); }

        /// <summary>Adds the [Test] methods of the class, in the order they are written.</summary>
        public void AddTests(Type type)
        {
            const BindingFlags all = BindingFlags.Static | BindingFlags.Public | BindingFlags.NonPublic;
            foreach (MethodInfo method in type.GetMethods(all).OrderBy(m => m.MetadataToken))
            {
                if (!method.IsDefined(typeof(TestAttribute), false)) continue;
                if (method.GetParameters().Length != 0 || method.ReturnType != typeof(void))
                    throw new InvalidOperationException(type.Name + "." + method.Name +
                                                        ": a [Test] method takes nothing and returns void");
                Add(type.Name + "." + method.Name, (Action)Delegate.CreateDelegate(typeof(Action), method));
            }
        }

        /// <summary>Adds the [Test] methods of every class of the assembly, class by class in name order.</summary>
        public void AddTests(Assembly assembly)
        {
            foreach (Type type in assembly.GetTypes().OrderBy(t => t.FullName, StringComparer.Ordinal))
                AddTests(type);
        }

        /// <summary>Runs the tests whose name contains filter (all if null); returns the number that failed.</summary>
        public int Run(string filter)
        {
            int run = 0;
            var failed = new List<string>();
            foreach (var test in tests)
            {
                if (filter != null && test.Key.IndexOf(filter, StringComparison.Ordinal) < 0) continue;
                ++run;
                Console.WriteLine("[ RUN      ] " + test.Key);
                var clock = Stopwatch.StartNew();
                try
                {
                    test.Value();
                    Console.WriteLine("[       OK ] " + test.Key + " (" + clock.ElapsedMilliseconds + " ms)");
                }
                catch (CheckFailed e)
                {
                    Console.WriteLine("  " + e.Message);
                    Console.WriteLine("[  FAILED  ] " + test.Key);
                    failed.Add(test.Key);
                }
                catch (Exception e)
                {
                    Console.WriteLine("  unexpected exception: " + e);
                    Console.WriteLine("[  FAILED  ] " + test.Key);
                    failed.Add(test.Key);
                }
            }
            var summary = new StringBuilder();
            summary.Append(run).Append(" tests, ").Append(Check.Count).Append(" checks, ")
                   .Append(failed.Count).Append(" failed");
            Console.WriteLine(summary.ToString());
            foreach (string name in failed) Console.WriteLine("  FAILED: " + name);
            if (run == 0)
            {
                Console.WriteLine("no test matched " + filter);
                return 1;
            }
            return failed.Count;
        }
    }
}
