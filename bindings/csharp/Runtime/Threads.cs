// The thread setting of the native library (hedge_set_max_threads / hedge_max_threads).
using System;
using System.Runtime.InteropServices;

namespace Hedge
{
    /// <summary>How many threads one call of the native library may run on, for the whole process.
    /// Only <see cref="HalfEdgeMesh.Subdivide"/> and the Hausdorff distance start worker threads,
    /// and join them before they return; their results do not depend on the count. Set
    /// <see cref="MaxThreads"/> to 1 to keep every call on the calling thread (inside a frame of the
    /// game loop, say).</summary>
    public static class Threads
    {
        /// <summary>The number of threads a call may run on, the calling thread included (at least
        /// 1). Setting 1 starts no worker thread at all; setting 0 restores the default, every core
        /// the process may run on. Any thread may set it at any time; a call already running keeps
        /// its count. A negative value: ArgumentOutOfRangeException.</summary>
        public static int MaxThreads
        {
            get
            {
                uint n;
                Status.Check(Native.hedge_max_threads(out n));
                return n > int.MaxValue ? int.MaxValue : (int)n;
            }
            set
            {
                if (value < 0)
                    throw new ArgumentOutOfRangeException("value", value,
                        "Threads.MaxThreads must be 0 (every core) or more, got " + value);
                Status.Check(Native.hedge_set_max_threads((uint)value));
            }
        }
    }

    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_set_max_threads(uint n);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_max_threads(out uint n);
    }
}
